// llvmpipe stops every loop of a shader invocation once 65535 iterations have run in it, all
// loops together (gallivm's LP_MAX_TGSI_LOOP_ITERATIONS). When the GLSL sample loop traced every
// sample of a pixel in one invocation, water_lily's naive preset at 16 samples (256 primary, 64
// shadow and 128 reflection steps per sample, the sky's octaves and petal layers inside) ran into
// it on the bench's view: the OSMesa frames came out darker, with about 9% fewer SDF evaluations,
// while 1 and 4 samples agreed. Since frames are plans of passes run once per sample, one
// invocation traces one ray; this frame (the bench's view of timelines/water_lily.toml at TIME 0,
// 16 samples, naive) must now agree bit for bit, evaluation counts included.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>
#include <memory>

#include "backends/cpu/cpu_backend.h"
#include "backends/gl/gl_backend.h"
#include "gl/filament_rule.h"
#include "gl/mesa_bits.h"
#include "scenes/registry.h"

namespace sdfreel {
namespace {

TEST(LlvmpipeLoopCap, WaterLilyNaiveAtSixteenSamplesAgrees) {
  const SceneInfo* info = find_scene("water_lily");
  ASSERT_NE(info, nullptr);
  std::unique_ptr<GlBackend> gl;
  try {
    gl = std::make_unique<GlBackend>();
  } catch (const std::exception& e) {
    GTEST_SKIP() << "OSMesa unavailable: " << e.what();
  }
  CpuBackend cpu{2};
  gl->begin(*info);
  cpu.begin(*info);
  FrameContext ctx;
  ctx.width = 16;
  ctx.height = 9;
  ctx.samples = 16;
  ctx.seed = 1;
  ctx.quality = Quality::Final;
  ctx.pose = CameraPose{{-0.6, 1.45, -2.4}, {0.2, 0.05, 4.0}, 45.0, 0.0};
  ctx.params = ParamValues(&info->params);
  finish_frame_context(ctx);
  ctx.march = naive_march_settings();
  RayStats cpu_stats, gl_stats;
  const ImageRGBA a = cpu.render(ctx, cpu_stats);
  const ImageRGBA b = gl->render(ctx, gl_stats);
  ASSERT_EQ(a.pixels.size(), b.pixels.size());
  int differing = 0;
  for (int y = 0; y < ctx.height; ++y)
    for (int x = 0; x < ctx.width; ++x)
      differing += std::memcmp(a.at(x, y), b.at(x, y), 4 * sizeof(float)) != 0;
  if (test::llvmpipe_bit_exact(*gl)) {
    EXPECT_EQ(differing, 0);
    EXPECT_EQ(cpu_stats.sdf_evals, gl_stats.sdf_evals);
  } else {  // another Mesa: the loops still run to the cap, within Filament's rule
    const test::FilamentVerdict v = test::filament_compare(a, b, "loop-cap-water-lily");
    EXPECT_TRUE(v.pass) << "mean " << v.mean << "/255, images in " << v.images;
    std::printf("%d of %d pixels differ (Mesa %s is not bit-exact)\n", differing,
                ctx.width * ctx.height, gl->versions()["mesa"].c_str());
  }
  // A view that marches far: about 100 evaluations per sample, each with loops inside.
  EXPECT_GT(cpu_stats.sdf_evals, uint64_t(16 * 9 * 16 * 50));
}

}  // namespace
}  // namespace sdfreel
