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
};

}  // namespace sdfreel
