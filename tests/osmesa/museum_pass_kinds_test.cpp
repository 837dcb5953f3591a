// The museum's frame by pass kind on both backends: seconds of its setup passes (the sun's shadow
// map), ray passes (sky), mesh passes (hall, exhibit 1) and image passes (occlusion, crepuscular
// rays, composite), from timing prefixes of its plan (the setup alone, then the sky, then up to the
// exhibits, then all), median of 5 runs, at 320x180 and one sample. Prints the CPU-against-llvmpipe
// ratio per kind (README, "The museum") and checks that the whole frames agree by Filament's rule.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <vector>

#include "backends/cpu/plan_runner.h"
#include "backends/osmesa/gl_plan_runner.h"
#include "backends/osmesa/osmesa_platform.h"
#include "backends/osmesa/shader_dir.h"
#include "osmesa/filament_rule.h"
#include "scenes/registry.h"

namespace sdfreel {
namespace {

constexpr int W = 320, H = 180, RUNS = 5;

template <class F>
double median_seconds(F&& run) {
  std::vector<double> s;
  for (int i = 0; i < RUNS; ++i) {
    const auto t0 = std::chrono::steady_clock::now();
    run();
    s.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  std::sort(s.begin(), s.end());
  return s[RUNS / 2];
}

FramePlan prefix(const FramePlan& plan, size_t passes) {
  FramePlan p = plan;
  p.passes.resize(passes);
  return p;
}

TEST(MuseumPassKinds, TimesPerKindAndTheFramesAgree) {
  std::unique_ptr<OsmesaPlatform> platform;
  try {
    platform = std::make_unique<OsmesaPlatform>();
  } catch (const GlPlatformError& e) {
    GTEST_SKIP() << "OSMesa unavailable: " << e.what();
  }
  GlDriver driver(*platform, find_shader_dir());
  const SceneInfo& info = *find_scene("museum");
  FrameContext ctx;
  ctx.width = W;
  ctx.height = H;
  ctx.samples = 1;
  ctx.scene_time = 2.0;
  ctx.pose = info.default_camera;
  ctx.params = ParamValues(&info.params);
  finish_frame_context(ctx);
  std::unique_ptr<Scene> scene = info.make();
  scene->prepare(ctx);
  const FramePlan plan = scene->frame_plan(ctx);
  // Pass order: sky (ray), hall and exhibits (mesh), then the image passes.
  size_t meshes_end = 1;
  while (meshes_end < plan.passes.size() &&
         std::holds_alternative<MeshPass>(plan.passes[meshes_end]))
    ++meshes_end;
  ASSERT_TRUE(std::holds_alternative<RayPass>(plan.passes[0]));
  ASSERT_GT(meshes_end, 1u);
  std::vector<GlTextureBinding> textures;
  for (const ShaderTexture& t : scene->shader_textures())
    textures.push_back({t.name, driver.upload_texture(t)});
  const GlSceneInputs inputs{info.shader, scene->shader_uniforms(), textures};
  GlPlanRunner runner(driver);
  RayStats stats;
  const size_t ends[4] = {0, 1, meshes_end, plan.passes.size()};
  double cpu[4], gl[4];
  for (int k = 0; k < 4; ++k) {
    const FramePlan p = prefix(plan, ends[k]);
    runner.run(p, ctx, inputs, stats);  // compile and warm up
    cpu[k] = median_seconds([&] { run_plan_cpu(p, ctx, CpuRunSettings{}, stats); });
    gl[k] = median_seconds([&] { runner.run(p, ctx, inputs, stats); });
  }
  const char* names[4] = {"setup (sun shadow map)", "ray (sky)", "mesh (hall, exhibit 1)",
                          "image (occlusion, rays, composite)"};
  for (int k = 0; k < 4; ++k) {
    const double c = cpu[k] - (k ? cpu[k - 1] : 0.0), g = gl[k] - (k ? gl[k - 1] : 0.0);
    std::printf("museum %dx%d %-36s cpu %.4f s  osmesa %.4f s  osmesa/cpu %.2fx\n", W, H, names[k],
                c, g, g / c);
  }
  std::printf("museum %dx%d %-36s cpu %.4f s  osmesa %.4f s  osmesa/cpu %.2fx\n", W, H,
              "whole frame", cpu[3], gl[3], gl[3] / cpu[3]);
  const test::FilamentVerdict v =
      test::filament_compare(run_plan_cpu(plan, ctx, CpuRunSettings{}, stats),
                             runner.run(plan, ctx, inputs, stats), "museum-pass-kinds");
  EXPECT_TRUE(v.pass) << "mean " << v.mean << "/255, share over 5/255 " << v.share_over_5;
}

}  // namespace
}  // namespace sdfreel
