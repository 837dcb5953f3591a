#include "backends/cpu/plan_runner.h"

#include <stdexcept>

#include "backends/cpu/cpu_image_pass.h"
#include "backends/cpu/cpu_mesh_pass.h"
#include "backends/cpu/cpu_ray_pass.h"
#include "backends/cpu/cpu_ray_pass_resolved.h"
#include "render/quality.h"
#include "render/tiling.h"

namespace sdfreel {

namespace {

// Pixels a task of the per-sample sums adds up.
constexpr size_t kPixelsPerTask = 1 << 14;

// Adds the sample's colour (all four channels, as the fixed sum always did) to live pixels, and to
// `odd` too when given (the odd samples' sum): one pass over the colour for both.
void add_live(const ImageRGBA& colour, const LivePixels& live, ImageRGBA& sum, ImageRGBA* odd,
              int threads) {
  const bool every = live.all_live();  // then plain loops, in lanes
  for_each_range(sum.pixels.size() / 4, kPixelsPerTask, threads, [&](size_t begin, size_t end) {
    if (every) {
      const float* from = colour.pixels.data();
      for (size_t i = begin * 4; i < end * 4; ++i) sum.pixels[i] += from[i];
      if (odd)
        for (size_t i = begin * 4; i < end * 4; ++i) odd->pixels[i] += from[i];
      return;
    }
    for (size_t i = begin; i < end; ++i)
      if (live.live(i))
        for (size_t c = 0; c < 4; ++c) {
          sum.pixels[i * 4 + c] += colour.pixels[i * 4 + c];
          if (odd) odd->pixels[i * 4 + c] += colour.pixels[i * 4 + c];
        }
  });
}

// Whether anything reads the SDF-evaluation counts target: the caller, or a pass's input. When
// nothing does, ray passes still write it, but clearing it before every sample changes nothing.
bool evals_are_read(const FramePlan& plan, const std::vector<float>* evals) {
  if (evals) return true;
  auto reads = [](const std::vector<ImageInput>& inputs) {
    for (const ImageInput& in : inputs)
      if (in.target == SDF_EVALS_TARGET) return true;
    return false;
  };
  for (const std::vector<Pass>* passes : {&plan.setup_passes, &plan.passes})
    for (const Pass& pass : *passes) {
      if (const auto* mesh = std::get_if<MeshPass>(&pass); mesh && reads(mesh->inputs)) return true;
      if (const auto* image = std::get_if<ImagePass>(&pass); image && reads(image->inputs))
        return true;
    }
  return false;
}

}  // namespace

void run_pass(const Pass& pass, const CpuPassContext& pc, CpuTargets& targets, RayStats& stats,
              MeshPassCache* cache) {
  if (const auto* ray = std::get_if<RayPass>(&pass)) {
    run_ray_pass(*ray, pc, targets, stats);
  } else if (const auto* mesh = std::get_if<MeshPass>(&pass)) {
    MeshPassCache fresh;
    run_mesh_pass(*mesh, pc, targets, cache ? *cache : fresh);
  } else {
    run_image_pass(std::get<ImagePass>(pass), pc, targets);
  }
}

ImageRGBA run_plan_cpu(const FramePlan& plan, const FrameContext& ctx, const CpuRunSettings& s,
                       RayStats& stats, SampleCounts* counts, std::vector<float>* evals) {
  CpuPassContext pc{
      ctx,
      glm::vec2(0.5f),
      make_camera_model(ctx.camera, ctx.width, ctx.height, plan.near_plane, plan.far_plane),
      footprint_angle(ctx.camera.tan_half_fov, ctx.height),
      s.threads,
      s.tile_size,
      s.packets};
  if (const RayPass* ray = resolvable_ray_pass(plan); ray && s.packets) {
    glm::vec4 clear(0.0f);
    for (const TargetSpec& t : plan_targets(plan))
      if (t.name == COLOUR_TARGET) clear = t.clear;
    return run_ray_pass_resolved(*ray, pc, clear, stats, counts, evals);
  }
  CpuTargets targets(plan_targets(plan), ctx.width, ctx.height, s.threads);
  targets.clear();
  if (!evals_are_read(plan, evals)) targets.skip_per_sample_clear(SDF_EVALS_TARGET);
  for (const Pass& pass : plan.setup_passes) run_pass(pass, pc, targets, stats);
  LivePixels live(sampling_of(ctx), ctx.width, ctx.height, s.threads);
  // The odd samples' sum only when a decision will read it (adaptive sampling).
  ImageRGBA sum(ctx.width, ctx.height), sum_odd;
  if (live.decides()) sum_odd = ImageRGBA(ctx.width, ctx.height);
  std::vector<MeshPassCache> caches(plan.passes.size());  // one per pass, for the frame
  if (evals) evals->assign(size_t(ctx.width) * ctx.height, 0.0f);
  for (int i = 0; i < int(ctx.sample_offsets.size()); ++i) {
    if (live.round_ends_at(i) && live.decide(i, sum, sum_odd) == 0) break;
    pc.offset = ctx.sample_offsets[size_t(i)];
    targets.clear_per_sample();
    for (size_t p = 0; p < plan.passes.size(); ++p)
      run_pass(plan.passes[p], pc, targets, stats, &caches[p]);
    const ImageRGBA& colour = targets.get(COLOUR_TARGET, "resolve");
    add_live(colour, live, sum, (i & 1) && !sum_odd.pixels.empty() ? &sum_odd : nullptr, s.threads);
    if (evals) {
      const ImageRGBA& e = targets.get(SDF_EVALS_TARGET, "resolve");
      for_each_range(evals->size(), kPixelsPerTask, s.threads, [&](size_t begin, size_t end) {
        for (size_t k = begin; k < end; ++k)
          if (live.live(k)) (*evals)[k] += e.pixels[k * 4];
      });
    }
  }
  // Times 1 / count, as the samples' mean always was; alpha is coverage, 1 for every frame.
  normalise_sums(sum, live.counts(), s.threads);
  if (counts) *counts = live.counts();
  return sum;
}

}  // namespace sdfreel
