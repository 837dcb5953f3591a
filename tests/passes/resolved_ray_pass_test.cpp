// A plan of one colour ray pass runs on the CPU with every sample of a pixel in consecutive lanes
// (coherent packets); a plan with any further pass runs once per sample. The frame is the same sum
// in the same order either way, so every scene must give the same bits both ways.
#include <gtest/gtest.h>

#include <cstring>

#include "backends/cpu/cpu_ray_pass_resolved.h"
#include "backends/cpu/plan_runner.h"
#include "scenes/registry.h"

namespace sdfreel {
namespace {

FrameContext scene_context(const SceneInfo& info) {
  FrameContext ctx;
  ctx.width = 29;  // not a multiple of the tile size or of eight lanes
  ctx.height = 17;
  ctx.samples = 3;
  ctx.scene_time = ctx.video_time = 2.0;
  ctx.seed = 1;
  ctx.quality = Quality::Final;
  ctx.pose = info.default_camera;
  ctx.params = ParamValues(&info.params);
  finish_frame_context(ctx);
  return ctx;
}

// Writes into a target of its own: the colour target, and so the frame, stay as they were.
ImagePass side_pass() {
  ImagePass p;
  p.name = "side";
  p.output = "side";
  p.pixel = [](const ImageInputs&, int, int) { return glm::vec4(0.5f); };
  return p;
}

TEST(ResolvedRayPass, SameBitsAsThePlanRunOncePerSample) {
  for (const SceneInfo& info : all_scenes()) {
    std::unique_ptr<Scene> scene = info.make();
    const FrameContext ctx = scene_context(info);
    scene->prepare(ctx);
    const FramePlan resolved = scene->frame_plan(ctx);
    // Plans of several passes (museum) never take the one-pass path: nothing to compare.
    if (!resolvable_ray_pass(resolved)) continue;
    FramePlan per_sample = resolved;
    per_sample.targets.push_back({"side", TargetKind::Colour, glm::vec4(0.0f)});
    per_sample.passes.push_back(side_pass());
    RayStats a, b;
    const ImageRGBA x = run_plan_cpu(resolved, ctx, CpuRunSettings{2, 16, true}, a);
    const ImageRGBA y = run_plan_cpu(per_sample, ctx, CpuRunSettings{2, 16, true}, b);
    ASSERT_EQ(x.pixels.size(), y.pixels.size());
    EXPECT_EQ(std::memcmp(x.pixels.data(), y.pixels.data(), x.pixels.size() * sizeof(float)), 0)
        << info.name;
    EXPECT_EQ(a.sdf_evals, b.sdf_evals) << info.name;
    // A scene without marches (lenticular_card meets its boxes analytically) counts none.
    if (!scene->distance_functions().empty()) {
      EXPECT_GT(a.sdf_evals, 0u) << info.name;
    }
  }
}

}  // namespace
}  // namespace sdfreel
