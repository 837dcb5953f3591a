#pragma once
// Runs a frame plan on the CPU: clear every target and run the setup passes once; then per sample
// offset, in list order, clear the targets that are not per-frame and run every pass in plan order;
// add the sample's "colour" to the frame's sum; the frame is sum / count. Adaptive sampling
// (render/adaptive_sampling.h): a plan of one ray pass runs per pixel (cpu_ray_pass_resolved.h);
// any other plan runs every pass over the whole frame for each sample while any pixel is live and
// adds the sample only to live pixels, so image passes still read every neighbour. Such plans get
// the same pictures, but save time only when every pixel stops.
#include <vector>

#include "backends/cpu/cpu_mesh_pass.h"
#include "backends/cpu/cpu_pass_context.h"
#include "backends/cpu/cpu_targets.h"
#include "render/frame_context.h"
#include "render/frame_plan.h"
#include "render/image.h"
#include "render/live_pixels.h"

namespace sdfreel {

struct CpuRunSettings {
  int threads = 0, tile_size = 16;
  bool packets = true;
};

// One pass of a plan into `targets`, by its kind; `cache` (optional) is the pass's memory from the
// frame's earlier samples (mesh passes: cpu_mesh_pass.h).
void run_pass(const Pass& pass, const CpuPassContext& pc, CpuTargets& targets, RayStats& stats,
              MeshPassCache* cache = nullptr);

// `counts`, when given, receives the samples each pixel took; `evals` the SDF evaluations of all a
// pixel's samples together, the "sdf_evals" target summed as GL sums it (row-major, top row first).
ImageRGBA run_plan_cpu(const FramePlan& plan, const FrameContext& ctx, const CpuRunSettings& s,
                       RayStats& stats, SampleCounts* counts = nullptr,
                       std::vector<float>* evals = nullptr);

}  // namespace sdfreel
