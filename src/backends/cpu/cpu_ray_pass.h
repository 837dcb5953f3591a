#pragma once
// A ray pass on the CPU for one sample: a ray through (x + offset) of every pixel, in packets of
// eight along the tile's rows (or one by one), written where the pass keeps it and, with a depth
// target, where the LESS test passes.
#include "backends/cpu/cpu_pass_context.h"
#include "backends/cpu/cpu_targets.h"
#include "render/frame_plan.h"

namespace sdfreel {

void run_ray_pass(const RayPass& pass, const CpuPassContext& pc, CpuTargets& targets,
                  RayStats& stats);

}  // namespace sdfreel
