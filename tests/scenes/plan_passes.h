#pragma once
// Runs a scene's frame plan on the CPU, one sample at the pixel centres, into targets a test can
// read: the setup passes, then the passes named (all when `names` is empty), in plan order.
#include <memory>
#include <set>
#include <string>

#include "backends/cpu/plan_runner.h"
#include "scenes/registry.h"

namespace sdfreel::test {

// The CPU context of `plan`'s passes at sample offset `offset`: tiles of 16, packets.
inline CpuPassContext plan_pass_context(const FramePlan& plan, const FrameContext& ctx,
                                        glm::vec2 offset, int threads) {
  return CpuPassContext{
      ctx,
      offset,
      make_camera_model(ctx.camera, ctx.width, ctx.height, plan.near_plane, plan.far_plane),
      footprint_angle(ctx.camera.tan_half_fov, ctx.height),
      threads,
      16,
      true};
}

inline CpuTargets run_plan_passes(const std::string& scene_name, const FrameContext& ctx,
                                  const std::set<std::string>& names = {}) {
  std::unique_ptr<Scene> scene = find_scene(scene_name)->make();
  scene->prepare(ctx);
  const FramePlan plan = scene->frame_plan(ctx);
  const CpuPassContext pc = plan_pass_context(plan, ctx, glm::vec2(0.5f), 1);
  CpuTargets targets(plan_targets(plan), ctx.width, ctx.height);
  targets.clear();
  RayStats stats;
  for (const Pass& pass : plan.setup_passes) run_pass(pass, pc, targets, stats);
  for (const Pass& pass : plan.passes)
    if (names.empty() || names.count(pass_name(pass))) run_pass(pass, pc, targets, stats);
  return targets;
}

}  // namespace sdfreel::test
