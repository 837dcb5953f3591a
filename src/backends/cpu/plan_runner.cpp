#include "backends/cpu/plan_runner.h"

#include <stdexcept>

#include "backends/cpu/cpu_image_pass.h"
#include "backends/cpu/cpu_mesh_pass.h"
#include "backends/cpu/cpu_ray_pass.h"
#include "backends/cpu/cpu_ray_pass_resolved.h"
#include "render/quality.h"

namespace sdfreel {

ImageRGBA run_plan_cpu(const FramePlan& plan, const FrameContext& ctx, const CpuRunSettings& s,
                       RayStats& stats) {
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
    return run_ray_pass_resolved(*ray, pc, clear, stats);
  }
  CpuTargets targets(plan_targets(plan), ctx.width, ctx.height);
  ImageRGBA sum(ctx.width, ctx.height);
  for (const glm::vec2& offset : ctx.sample_offsets) {
    pc.offset = offset;
    targets.clear();
    for (const Pass& pass : plan.passes) {
      if (const auto* ray = std::get_if<RayPass>(&pass))
        run_ray_pass(*ray, pc, targets, stats);
      else if (const auto* mesh = std::get_if<MeshPass>(&pass))
        run_mesh_pass(*mesh, pc, targets);
      else
        run_image_pass(std::get<ImagePass>(pass), pc, targets);
    }
    const ImageRGBA& colour = targets.get(COLOUR_TARGET, "resolve");
    for (size_t i = 0; i < sum.pixels.size(); ++i) sum.pixels[i] += colour.pixels[i];
  }
  // Times 1 / count, as the samples' mean always was; alpha is coverage, 1 for every frame.
  const float inv_samples = 1.0f / float(ctx.sample_offsets.size());
  for (size_t i = 0; i < sum.pixels.size(); i += 4) {
    sum.pixels[i] *= inv_samples;
    sum.pixels[i + 1] *= inv_samples;
    sum.pixels[i + 2] *= inv_samples;
    sum.pixels[i + 3] = 1.0f;
  }
  return sum;
}

}  // namespace sdfreel
