// A frame's cost by pass on both backends, for the plans of several passes (the museum and the
// fur; the lenticular card is one pass, its bits held by the agreement test): CPU seconds of each
// pass from timing prefixes of the plan (the first pass alone, then the first two, ...; a pass
// costs its prefix minus the one before), medians of RUNS runs at 320x180 and SAMPLES samples,
// summed by pass kind. The clock is the process's CPU time, which counts llvmpipe's threads as well
// as ours: on a shared, loaded machine wall time measures the scheduler more than the backends.
// Prints each pass and the CPU-against-llvmpipe ratio per kind (docs/scenes/museum.md, "Speed
// against llvmpipe"), and checks that the whole frames agree by Filament's rule. Run: test_gl
// --gtest_filter='*PassKinds*'.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <ctime>
#include <vector>

#include "backends/cpu/plan_runner.h"
#include "backends/gl/gl_plan_runner.h"
#include "backends/gl/gl_platform_choice.h"
#include "backends/gl/shader_dir.h"
#include "gl/filament_rule.h"
#include "scenes/registry.h"

namespace sdfreel {
namespace {

constexpr int W = 320, H = 180, RUNS = 5, SAMPLES = 4;

template <class F>
double median_seconds(F&& run) {
  std::vector<double> s;
  for (int i = 0; i < RUNS; ++i) {
    timespec t0, t1;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t0);
    run();
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t1);
    s.push_back(double(t1.tv_sec - t0.tv_sec) + 1e-9 * double(t1.tv_nsec - t0.tv_nsec));
  }
  std::sort(s.begin(), s.end());
  return s[RUNS / 2];
}

FramePlan prefix(const FramePlan& plan, size_t passes) {
  FramePlan p = plan;
  p.passes.resize(passes);
  return p;
}

const char* kind_name(const Pass& p) {
  if (std::holds_alternative<RayPass>(p)) return "ray";
  if (std::holds_alternative<MeshPass>(p)) return "mesh";
  return "image";
}

struct SceneTime {
  const char* scene;
  double time;  // seconds: the exhibits in motion (the fur after its push)
};

class PassKinds : public ::testing::TestWithParam<SceneTime> {};

TEST_P(PassKinds, TimesPerPassAndKindAndTheFramesAgree) {
  std::unique_ptr<GlPlatform> platform;
  try {
    platform = make_gl_platform({});
  } catch (const GlPlatformError& e) {
    GTEST_SKIP() << "GL platform unavailable: " << e.what();
  }
  GlDriver driver(*platform, find_shader_dir());
  const SceneInfo& info = *find_scene(GetParam().scene);
  FrameContext ctx;
  ctx.width = W;
  ctx.height = H;
  ctx.samples = SAMPLES;
  ctx.scene_time = GetParam().time;
  ctx.pose = info.default_camera;
  ctx.params = ParamValues(&info.params);
  finish_frame_context(ctx);
  std::unique_ptr<Scene> scene = info.make();
  scene->prepare(ctx);
  const FramePlan plan = scene->frame_plan(ctx);
  ASSERT_GT(plan.passes.size(), 1u);
  std::vector<GlTextureBinding> textures;
  for (const ShaderTexture& t : scene->shader_textures())
    textures.push_back({t.name, driver.upload_texture(t)});
  const GlSceneInputs inputs{info.shader, scene->shader_uniforms(), textures};
  GlPlanRunner runner(driver, 1);
  RayStats stats;
  const size_t n = plan.passes.size();
  std::vector<double> cpu(n + 1, 0.0), gl(n + 1, 0.0);  // [k]: the first k passes
  for (size_t k = 1; k <= n; ++k) {
    const FramePlan p = prefix(plan, k);
    runner.run(p, ctx, inputs, stats);  // compile and warm up
    cpu[k] = median_seconds([&] { run_plan_cpu(p, ctx, CpuRunSettings{}, stats); });
    gl[k] = median_seconds([&] { runner.run(p, ctx, inputs, stats); });
  }
  const char* kinds[3] = {"ray", "mesh", "image"};
  double kind_cpu[3] = {0, 0, 0}, kind_gl[3] = {0, 0, 0};
  for (size_t k = 1; k <= n; ++k) {
    const Pass& pass = plan.passes[k - 1];
    const double c = cpu[k] - cpu[k - 1], g = gl[k] - gl[k - 1];
    std::printf("%s %dx%d  %-5s %-28s cpu %.4f s  osmesa %.4f s (CPU seconds)\n", info.name.c_str(),
                W, H, kind_name(pass), pass_name(pass).c_str(), c, g);
    for (int j = 0; j < 3; ++j)
      if (std::string(kinds[j]) == kind_name(pass)) kind_cpu[j] += c, kind_gl[j] += g;
  }
  for (int j = 0; j < 3; ++j)
    if (kind_cpu[j] != 0.0 || kind_gl[j] != 0.0)
      std::printf("%s %dx%d  kind %-5s cpu %.4f s  osmesa %.4f s  osmesa/cpu %.2fx\n",
                  info.name.c_str(), W, H, kinds[j], kind_cpu[j], kind_gl[j],
                  kind_gl[j] / kind_cpu[j]);
  std::printf("%s %dx%d  whole frame cpu %.4f s  osmesa %.4f s  osmesa/cpu %.2fx\n",
              info.name.c_str(), W, H, cpu[n], gl[n], gl[n] / cpu[n]);
  const test::FilamentVerdict v =
      test::filament_compare(run_plan_cpu(plan, ctx, CpuRunSettings{}, stats),
                             runner.run(plan, ctx, inputs, stats), "pass-kinds-" + info.name);
  EXPECT_TRUE(v.pass) << "mean " << v.mean << "/255, share over 5/255 " << v.share_over_5;
}

INSTANTIATE_TEST_SUITE_P(Scenes, PassKinds,
                         ::testing::Values(SceneTime{"museum", 2.0}, SceneTime{"fur", 2.0}),
                         [](const ::testing::TestParamInfo<SceneTime>& i) {
                           return std::string(i.param.scene);
                         });

}  // namespace
}  // namespace sdfreel
