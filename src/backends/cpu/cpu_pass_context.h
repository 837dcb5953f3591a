#pragma once
// What every CPU pass of one sample needs: the frame, the sample's offset and camera, and how to
// spread work over threads.
#include <glm/glm.hpp>

#include "render/camera_model.h"
#include "render/frame_context.h"

namespace sdfreel {

struct CpuPassContext {
  const FrameContext& frame;
  glm::vec2 offset;    // this sample's sub-pixel offset
  CameraModel camera;  // view and projection of the plan's near/far
  float pixel_angle;   // footprint_angle of the frame (quality.h)
  int threads = 0, tile_size = 16;
  bool packets = true;  // eight-lane ray packets, or one ray at a time

  // A mesh pass's tiles are larger: its work is per triangle and tile it touches (set-up, edges),
  // and its pixels cost about the same, so there is little imbalance for small tiles to even out.
  // 64 where ray passes take 16: a fur frame 5% less CPU time, same bits.
  int mesh_tile_size() const { return tile_size * 4; }
};

}  // namespace sdfreel
