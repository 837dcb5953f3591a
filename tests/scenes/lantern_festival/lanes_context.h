#pragma once
// The frame the lantern lane tests prepare the scene for: a 16x9 final-quality frame of the
// default camera at `time` with the given texture seed.
#include <cstdint>

#include "render/frame_context.h"
#include "scenes/registry.h"

namespace sdfreel::test {

inline FrameContext lantern_lanes_context(double time, uint64_t seed = 1) {
  const SceneInfo* info = find_scene("lantern_festival");
  FrameContext ctx;
  ctx.width = 16;
  ctx.height = 9;
  ctx.scene_time = time;
  ctx.video_time = time;
  ctx.seed = seed;
  ctx.quality = Quality::Final;
  ctx.pose = info->default_camera;
  ctx.params = ParamValues(&info->params);
  finish_frame_context(ctx);
  return ctx;
}

}  // namespace sdfreel::test
