#pragma once
// What the CPU mesh pass keeps between its stages: vertices after the vertex stage and their window
// transforms, and the triangles of one sample as indices into them with their exact pixel range.
#include <glm/glm.hpp>
#include <vector>

#include "backends/cpu/cpu_mesh_pass.h"

namespace sdfreel {

// A vertex's window position (y up, pixel centres at +0.5), 1 / w and window depth z_w.
struct WindowVertex {
  glm::dvec2 p;
  double inv_w, depth;
};

// A triangle that covers at least one pixel centre's bounding range: its vertices in counter-
// clockwise window order (so edge tests and the top-left rule are one case) as indices into the
// vertex arrays (the placed vertices', or its batch's near-clipped corners' when `clipped`), its
// area in that order, and the window pixels [x0, x1] x [y0, y1] whose centres lie within its
// bounds, clipped to the frame (window rows: image row = height - 1 - window row).
struct RasterTriangle {
  unsigned v[3];
  unsigned instance;
  int x0, x1, y0, y1;
  double area;
  bool front, clipped;
};

// Where a triangle's vertices are: window transforms and varyings, same indices.
struct VertexArrays {
  const WindowVertex* window;
  const glm::vec3 *world, *normal;
  const glm::vec2* uv;
};

// The triangles of a run of whole instances, set up by one thread, in mesh order, and the ones of
// them whose pixels touch each tile; with the corners of its near-clipped triangles.
struct TriangleBatch {
  size_t first_instance = 0, end_instance = 0;
  std::vector<RasterTriangle> triangles;
  std::vector<std::vector<unsigned>> bins;
  std::vector<glm::vec3> world, normal;
  std::vector<glm::vec2> uv;
  std::vector<WindowVertex> window;
  VertexArrays clipped() const { return {window.data(), world.data(), normal.data(), uv.data()}; }
};

struct MeshPassCache::Data {
  const MeshPass* placed_for = nullptr;  // the pass whose vertices world, normal and uv hold
  // Varyings of every vertex of every instance: instance * vertex_count + vertex.
  std::vector<glm::vec3> world, normal;
  std::vector<glm::vec2> uv;
  std::vector<glm::vec4> clip;         // this sample's clip positions, same order
  std::vector<WindowVertex> window;    // and their window transforms
  std::vector<TriangleBatch> batches;  // this sample's, reused
  VertexArrays placed() const { return {window.data(), world.data(), normal.data(), uv.data()}; }
};

}  // namespace sdfreel
