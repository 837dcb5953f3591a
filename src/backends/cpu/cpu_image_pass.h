#pragma once
// An image pass on the CPU: the pass's row function (or else its pixel function) over every pixel
// of its output, in tiles.
// Pixels are independent and read only other targets, so threads never change bits.
#include "backends/cpu/cpu_pass_context.h"
#include "backends/cpu/cpu_targets.h"
#include "render/frame_plan.h"

namespace sdfreel {

void run_image_pass(const ImagePass& pass, const CpuPassContext& pc, CpuTargets& targets);

}  // namespace sdfreel
