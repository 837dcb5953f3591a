// CPU against GL on a plan with a mesh pass and a depth-composited ray pass (gl/mixed_plan):
// the mesh passes agree by Filament's rule (at most 0.1% of pixels off by more than 5/255, mean
// below 0.5/255, on display values), a diff image written on failure; the ray pass alone stays
// bit-identical; the CPU rasteriser gives the same bits on any thread count.
#include "gl/mixed_plan.h"

#include <gtest/gtest.h>

#include "backends/cpu/plan_runner.h"
#include "backends/gl/gl_plan_runner.h"
#include "gl/filament_rule.h"
#include "gl/gl_fixture.h"

namespace sdfreel {
namespace {

using test::GlTest;

TEST_F(GlTest, MixedPlanCpuAgreesWithGlByFilamentsRule) {
  const FrameContext ctx = test::mixed_context(160, 90, 4);
  const FramePlan plan = test::mixed_plan(ctx);
  GlPlanRunner runner(*driver, 1);
  RayStats gl_stats, cpu_stats, cpu2_stats;
  const ImageRGBA gl = runner.run(plan, ctx, {}, gl_stats);
  const ImageRGBA cpu = run_plan_cpu(plan, ctx, CpuRunSettings{1, 16, true}, cpu_stats);
  EXPECT_EQ(run_plan_cpu(plan, ctx, CpuRunSettings{2, 7, true}, cpu2_stats).pixels, cpu.pixels);
  // (SDF evaluation counts differ by design here: GL's sdf_evals target keeps only fragments that
  // were written, so discarded and depth-failed rays of the sphere go uncounted.)
  const test::FilamentVerdict v = test::filament_compare(cpu, gl, "mixed-plan");
  std::printf("mixed plan 160x90x4: mean %.4f/255, share over 5/255 %.4f%%, max %.2f/255\n", v.mean,
              v.share_over_5 * 100.0, v.max);
  if (!v.images.empty()) std::printf("images in %s\n", v.images.c_str());
  EXPECT_LE(v.share_over_5, FILAMENT_MAX_SHARE_OVER_5);
  EXPECT_LT(v.mean, FILAMENT_MAX_MEAN);
}

TEST_F(GlTest, RayPassWithDepthIsBitIdentical) {
  const FrameContext ctx = test::mixed_context(64, 36, 2);
  FramePlan plan = test::mixed_plan(ctx);
  plan.passes.erase(plan.passes.begin());  // the sphere alone, depth written over the cleared 1
  GlPlanRunner runner(*driver, 1);
  RayStats stats;
  const ImageRGBA gl = runner.run(plan, ctx, {}, stats);
  const ImageRGBA cpu = run_plan_cpu(plan, ctx, {}, stats);
  EXPECT_EQ(gl.pixels, cpu.pixels);
  int lit = 0;  // the sphere is in view
  for (size_t i = 0; i < cpu.pixels.size(); i += 4) lit += cpu.pixels[i] > 0.0f;
  EXPECT_GT(lit, 100);
}

// Adaptive sampling through the per-sample loop of both runners (a ray pass with depth is not run
// per pixel): the same samples a pixel, the same sums, edges sampled more than the flat inside.
TEST_F(GlTest, AdaptiveRayPassWithDepthIsBitIdentical) {
  FrameContext ctx = test::mixed_context(64, 36, 1);
  ctx.adaptive = AdaptiveSampling{true, 2, 6, 0.01f};
  finish_frame_context(ctx);
  FramePlan plan = test::mixed_plan(ctx);
  plan.passes.erase(plan.passes.begin());
  GlPlanRunner runner(*driver, 1);
  RayStats stats;
  SampleCounts gl_counts, cpu_counts;
  const ImageRGBA gl = runner.run(plan, ctx, {}, stats, &gl_counts);
  const ImageRGBA cpu = run_plan_cpu(plan, ctx, {}, stats, &cpu_counts);
  EXPECT_EQ(gl.pixels, cpu.pixels);
  EXPECT_EQ(gl_counts, cpu_counts);
  int at_min = 0, at_max = 0;
  for (uint16_t n : cpu_counts) {
    at_min += n == 2;
    at_max += n == 6;
  }
  EXPECT_GT(at_min, 100);
  EXPECT_GT(at_max, 10);
}

}  // namespace
}  // namespace sdfreel
