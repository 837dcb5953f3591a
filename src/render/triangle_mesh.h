#pragma once
// A triangle mesh in model space, for mesh passes on both backends: positions (xyz), optional
// normals (xyz) and uvs (uv) per vertex, and indices (three per triangle; empty: vertices in
// order). Front faces wind counter-clockwise as the camera sees them (GL's default).
#include <vector>

namespace sdfreel {

struct TriangleMesh {
  std::vector<float> positions, normals, uvs;
  std::vector<unsigned> indices;
  size_t vertex_count() const { return positions.size() / 3; }
  size_t triangle_count() const { return (indices.empty() ? vertex_count() : indices.size()) / 3; }
  unsigned index(size_t i) const { return indices.empty() ? unsigned(i) : indices[i]; }
};

}  // namespace sdfreel
