#pragma once
// The CPU mesh pass's stages before rasterisation: the vertex stage (once per frame), this
// sample's window transforms, near clipping, culling and each triangle's exact pixel range, and
// the triangles of each tile.
#include <glm/glm.hpp>

#include "backends/cpu/mesh_pass_data.h"

namespace sdfreel {

// Places every vertex of every instance in world space with its normal and uv, unless d already
// holds this pass's (world positions and normals do not depend on the sample offset).
void place_vertices(const MeshPass& pass, MeshPassCache::Data& d);

// This sample's triangles on a target of `size` into d.triangles, in mesh order: those with no
// area, culled, or whose bounds hold no pixel centre of the frame are dropped (they would cover
// nothing).
void setup_triangles(const MeshPass& pass, const glm::mat4& view_proj, const glm::ivec2& size,
                     MeshPassCache::Data& d);

// The triangles whose pixel range touches each tile, in mesh order (so each pixel still sees its
// fragments in the same order whatever the tiling).
void bin_by_tile(const MeshPassCache::Data& d, const glm::ivec2& size, int tile_size,
                 std::vector<std::vector<unsigned>>& bins);

// edge(a, b, p): twice the signed area of (a, b, p), positive when p is left of a -> b.
inline double edge(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& p) {
  return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
}

// The pixels [first, last] of n whose centres (pixel + 0.5) lie in [lo, hi]; false if none (or a
// bound is NaN).
bool centre_range(double lo, double hi, int n, int& first, int& last);

}  // namespace sdfreel
