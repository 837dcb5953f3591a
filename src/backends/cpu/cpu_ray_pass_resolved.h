#pragma once
// The common plan, one ray pass into the colour target with no depth (every full-screen ray
// march), run with every sample of a pixel in consecutive lanes: a packet then holds eight samples
// of one pixel (coherent rays), not eight pixels of one sample, which made sdf_morph about 25%
// and the lanterns about 13% slower. Same values summed in the same order: the same bits as the
// plan run once per sample.
//
// Adaptive sampling (render/adaptive_sampling.h) runs here per pixel, tile by tile: each round
// gathers the (pixel, sample) pairs of the tile's live pixels into full packets of eight, so lanes
// do not idle while pixels stop at different rounds. A lane's radiance depends only on its own ray
// (the packet-path and resolved-pass tests hold scenes to that), so the grouping never changes
// bits. Fixed sampling is the one-round case (minimum = maximum = samples).
#include <optional>
#include <vector>

#include "backends/cpu/cpu_pass_context.h"
#include "render/frame_plan.h"
#include "render/image.h"
#include "render/live_pixels.h"

namespace sdfreel {

// The plan's only pass when it is such a ray pass with packet code, else null.
const RayPass* resolvable_ray_pass(const FramePlan& plan);

// The frame (sum of a pixel's samples times 1/its count, alpha 1); `clear` is the colour target's
// clear value, which a sample that the pass does not keep adds. `counts`, when given, receives
// the samples each pixel took; `evals` the SDF evaluations of all a pixel's samples together
// (row-major, top row first; zeros when the pass counts none).
ImageRGBA run_ray_pass_resolved(const RayPass& pass, const CpuPassContext& pc,
                                const glm::vec4& clear, RayStats& stats,
                                SampleCounts* counts = nullptr,
                                std::vector<float>* evals = nullptr);

}  // namespace sdfreel
