#pragma once
// The CPU mesh pass's stages before rasterisation: the vertex stage (once per frame), this
// sample's window transforms, near clipping, culling and each triangle's exact pixel range, and
// the triangles of each tile.
#include <glm/glm.hpp>

#include "backends/cpu/mesh_pass_data.h"

namespace sdfreel {

// Places every vertex of every instance in world space with its normal and uv, unless d already
// holds this pass's (world positions and normals do not depend on the sample offset). Instances
// run on `threads` threads (0: all cores).
void place_vertices(const MeshPass& pass, int threads, MeshPassCache::Data& d);

// This sample's triangles on a target of `size` into d.batches, in mesh order, binned by tiles of
// tile_size: those with no area, culled, or whose bounds hold no pixel centre of the frame are
// dropped (they would cover nothing). Batches of whole instances run on `threads` threads (0: all
// cores); the result does not depend on how many.
void setup_batches(const MeshPass& pass, const glm::mat4& view_proj, const glm::ivec2& size,
                   int tile_size, int threads, MeshPassCache::Data& d);

// edge(a, b, p): twice the signed area of (a, b, p), positive when p is left of a -> b.
inline double edge(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& p) {
  return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
}

// The pixels [first, last] of n whose centres (pixel + 0.5) lie in [lo, hi]; false if none (or a
// bound is NaN).
bool centre_range(double lo, double hi, int n, int& first, int& last);

}  // namespace sdfreel
