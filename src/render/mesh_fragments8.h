#pragma once
// Eight fragments of one triangle in lanes, for a mesh pass's optional CPU fast path
// (MeshPass::shade8): the CPU rasteriser gathers up to eight covered samples that passed the
// early depth test, interpolates their varyings in lanes and shades them at once. Lanes past
// `count` repeat lane 0's values, so they stay finite; their colours are ignored.
#include <glm/glm.hpp>

#include "sdf/lanes.h"

namespace sdfreel {

struct ImageInputs;

struct MeshFragments8 {
  V3x8 world_position, world_normal;  // normal interpolated, not normalised
  V2x8 uv;
  glm::vec4 instance_data;  // the triangle's: one instance per triangle
  bool front_facing;
  const ImageInputs* inputs = nullptr;
  int count = LANES;  // lanes that hold a fragment
};

struct FragmentColours8 {
  F8 r, g, b, a;
};

}  // namespace sdfreel
