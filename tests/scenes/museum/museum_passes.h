#pragma once
// Runs the museum plan's own passes on the CPU, one sample at the pixel centres, into targets a
// test can read: the hall's colour and the depth after the setup passes (the sun's shadow map) and
// the passes named (in plan order), and the sun's shadow map.
#include <memory>
#include <set>
#include <string>

#include "backends/cpu/plan_runner.h"
#include "scenes/registry.h"

namespace sdfreel::test {

struct MuseumTargets {
  ImageRGBA colour, depth, sun_map;
};

inline MuseumTargets run_museum_passes(const FrameContext& ctx,
                                       const std::set<std::string>& names) {
  std::unique_ptr<Scene> scene = find_scene("museum")->make();
  scene->prepare(ctx);
  const FramePlan plan = scene->frame_plan(ctx);
  CpuPassContext pc{
      ctx,
      glm::vec2(0.5f),
      make_camera_model(ctx.camera, ctx.width, ctx.height, plan.near_plane, plan.far_plane),
      footprint_angle(ctx.camera.tan_half_fov, ctx.height),
      1,
      16,
      true};
  CpuTargets targets(plan_targets(plan), ctx.width, ctx.height);
  targets.clear();
  RayStats stats;
  for (const Pass& pass : plan.setup_passes) run_pass(pass, pc, targets, stats);
  for (const Pass& pass : plan.passes)
    if (names.count(pass_name(pass))) run_pass(pass, pc, targets, stats);
  return {targets.get("hall", "test"), targets.get(DEPTH_TARGET, "test"),
          targets.get("sun_shadow", "test")};
}

}  // namespace sdfreel::test
