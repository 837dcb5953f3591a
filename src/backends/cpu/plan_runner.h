#pragma once
// Runs a frame plan on the CPU: per sample offset, in list order, clear the targets and run every
// pass in plan order; add the sample's "colour" to the frame's sum; the frame is sum / count.
#include "render/frame_context.h"
#include "render/frame_plan.h"
#include "render/image.h"

namespace sdfreel {

struct CpuRunSettings {
  int threads = 0, tile_size = 16;
  bool packets = true;
};

ImageRGBA run_plan_cpu(const FramePlan& plan, const FrameContext& ctx, const CpuRunSettings& s,
                       RayStats& stats);

}  // namespace sdfreel
