#pragma once
// Rasterises one triangle of a CPU mesh pass over one tile: coverage at pixel centres with the
// top-left rule, window depth linear in window space, perspective-correct varyings, then the
// pass's shading, depth test and write and alpha discard.
#include "backends/cpu/mesh_pass_data.h"
#include "render/tiling.h"

namespace sdfreel {

struct MeshTargets {
  ImageRGBA* colour;  // null: depth only
  ImageRGBA* depth;   // null: none
  bool test, write_depth;
  const ImageInputs* inputs;
};

// v: the arrays s's vertex indices refer to.
void rasterise(const RasterTriangle& s, const VertexArrays& v, const MeshPass& pass, const Tile& t,
               int height, const MeshTargets& out);

}  // namespace sdfreel
