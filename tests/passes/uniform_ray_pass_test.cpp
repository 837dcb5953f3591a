// A ray pass that declares one colour for all its rays (RayPass::uniform_colour, a plain
// background) is filled on the CPU instead of traced: for every scene, every surface output and
// the hit mask, each such pass must leave its colour and SDF-evaluation targets with the bits that
// tracing it leaves, at a sample offset off the pixel centre.
#include <gtest/gtest.h>

#include <cstring>

#include "scenes/plan_passes.h"

namespace sdfreel {
namespace {

FrameContext scene_context(const SceneInfo& info, bool hit_mask, int surface) {
  FrameContext ctx;
  ctx.width = 29;  // not a multiple of the tile size or of eight lanes
  ctx.height = 17;
  ctx.scene_time = ctx.video_time = 2.0;
  ctx.pose = info.default_camera;
  ctx.params = ParamValues(&info.params);
  finish_frame_context(ctx);
  ctx.march.hit_mask = hit_mask;
  ctx.march.surface = surface;
  return ctx;
}

// The targets after `pass` alone, on targets cleared to the plan's values.
CpuTargets after(const RayPass& pass, const FramePlan& plan, const FrameContext& ctx) {
  const CpuPassContext pc = test::plan_pass_context(plan, ctx, glm::vec2(0.25f, 0.75f), 2);
  CpuTargets targets(plan_targets(plan), ctx.width, ctx.height);
  targets.clear();
  RayStats stats;
  run_pass(pass, pc, targets, stats);
  EXPECT_EQ(stats.sdf_evals, 0u) << pass.name;
  return targets;
}

bool same_bits(const ImageRGBA& a, const ImageRGBA& b) {
  return a.pixels.size() == b.pixels.size() &&
         std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(float)) == 0;
}

TEST(UniformRayPass, FillingGivesTheBitsOfTracing) {
  int checked = 0;
  for (const SceneInfo& info : all_scenes())
    for (bool hit_mask : {false, true})
      for (int surface : {SURFACE_COLOUR, SURFACE_DISTANCE, SURFACE_NORMAL}) {
        std::unique_ptr<Scene> scene = info.make();
        const FrameContext ctx = scene_context(info, hit_mask, surface);
        scene->prepare(ctx);
        const FramePlan plan = scene->frame_plan(ctx);
        for (const Pass& p : plan.passes) {
          const RayPass* filled = std::get_if<RayPass>(&p);
          if (!filled || !filled->uniform_colour) continue;
          RayPass traced = *filled;
          traced.uniform_colour.reset();
          CpuTargets a = after(*filled, plan, ctx), b = after(traced, plan, ctx);
          for (const std::string& target : {filled->colour, filled->sdf_evals})
            EXPECT_TRUE(same_bits(a.get(target, "test"), b.get(target, "test")))
                << info.name << " " << filled->name << " " << target << ", hit mask " << hit_mask
                << ", surface " << surface;
          ++checked;
        }
      }
  EXPECT_GE(checked, 6);  // the fur's background, in every mode
}

}  // namespace
}  // namespace sdfreel
