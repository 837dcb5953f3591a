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
// vertex arrays, its area in that order, and the window pixels [x0, x1] x [y0, y1] whose centres
// lie within its bounds, clipped to the frame (window rows: image row = height - 1 - window row).
struct RasterTriangle {
  unsigned v[3];
  unsigned instance;
  int x0, x1, y0, y1;
  double area;
  bool front;
};

struct MeshPassCache::Data {
  const MeshPass* placed_for = nullptr;  // the pass whose vertices world, normal and uv hold
  size_t placed = 0;                     // vertices placed: instance * vertex_count + vertex
  // Varyings of every placed vertex, then of this sample's near-clipped corners.
  std::vector<glm::vec3> world, normal;
  std::vector<glm::vec2> uv;
  std::vector<glm::vec4> clip;            // this sample's clip positions of the placed vertices
  std::vector<WindowVertex> window;       // window transforms, same order as the varyings
  std::vector<RasterTriangle> triangles;  // this sample's, in mesh order, reused
  std::vector<std::vector<unsigned>> bins;
};

}  // namespace sdfreel
