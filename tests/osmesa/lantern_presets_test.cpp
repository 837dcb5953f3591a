// lantern_festival in process, on both backends: the GLSL twin computes the same linear floats as
// the C++ scene, bit for bit, and the same SDF evaluation count, for every march preset and mode
// the scene has (the cell walk of draft and final, the sphere tracing of reference, the naive
// preset, the hit-mask output) and at parameter extremes. A mismatch names the first pixels.
#include <gtest/gtest.h>

#include <cstring>
#include <memory>

#include "backends/cpu/cpu_backend.h"
#include "backends/osmesa/osmesa_backend.h"
#include "scenes/registry.h"

namespace sdfreel {
namespace {

constexpr int W = 64, H = 36;

const SceneInfo& lantern_info() {
  const SceneInfo* s = find_scene("lantern_festival");
  if (!s) throw std::runtime_error("lantern_festival is not registered");
  return *s;
}

FrameContext context(Quality quality, double time, const CameraPose& pose) {
  FrameContext ctx;
  ctx.width = W;
  ctx.height = H;
  ctx.samples = 1;
  ctx.scene_time = ctx.video_time = time;
  ctx.seed = 1;
  ctx.quality = quality;
  ctx.pose = pose;
  ctx.params = ParamValues(&lantern_info().params);
  finish_frame_context(ctx);
  return ctx;
}

// Between two columns of lanterns, looking along the corridor (as the default timeline does).
CameraPose corridor() {
  return CameraPose{{4.0, 0.5, -10.0}, {2.5, 0.1, 4.0}, 50.0, 0.0};
}

class LanternPresets : public ::testing::Test {
 protected:
  void SetUp() override {
    try {
      osmesa = std::make_unique<OsmesaBackend>();
    } catch (const std::exception& e) {
      GTEST_SKIP() << "OSMesa unavailable: " << e.what();
    }
    osmesa->begin(lantern_info());
    cpu.begin(lantern_info());
  }

  // Renders ctx on both backends and expects identical floats and SDF evaluation counts.
  void expect_identical(const FrameContext& ctx, const std::string& what) {
    RayStats cpu_stats, gl_stats;
    const ImageRGBA a = cpu.render(ctx, cpu_stats);
    const ImageRGBA b = osmesa->render(ctx, gl_stats);
    ASSERT_EQ(a.pixels.size(), b.pixels.size()) << what;
    int differing = 0;
    for (int y = 0; y < H; ++y)
      for (int x = 0; x < W; ++x)
        if (std::memcmp(a.at(x, y), b.at(x, y), 4 * sizeof(float)) != 0 && differing++ < 3)
          ADD_FAILURE() << what << ": pixel (" << x << ", " << y << ") cpu (" << a.at(x, y)[0]
                        << ", " << a.at(x, y)[1] << ", " << a.at(x, y)[2] << "), osmesa ("
                        << b.at(x, y)[0] << ", " << b.at(x, y)[1] << ", " << b.at(x, y)[2] << ")";
    EXPECT_EQ(differing, 0) << what << ": pixels that differ";
    EXPECT_GT(cpu_stats.sdf_evals, uint64_t(W * H)) << what;
    EXPECT_EQ(cpu_stats.sdf_evals, gl_stats.sdf_evals) << what;
  }

  CpuBackend cpu{2};
  std::unique_ptr<OsmesaBackend> osmesa;
};

TEST_F(LanternPresets, QualityPresetsAreBitIdentical) {
  for (Quality q : {Quality::Draft, Quality::Final, Quality::Reference})
    expect_identical(context(q, 3.0, corridor()), quality_name(q));
}

TEST_F(LanternPresets, NaivePresetAndHitMaskAreBitIdentical) {
  FrameContext naive = context(Quality::Final, 3.0, corridor());
  naive.march = naive_march_settings();
  expect_identical(naive, "naive");
  naive.march.hit_mask = true;
  expect_identical(naive, "naive hit mask");
  FrameContext mask = context(Quality::Final, 3.0, corridor());
  mask.march.hit_mask = true;
  expect_identical(mask, "final hit mask");
}

TEST_F(LanternPresets, ParameterExtremesAreBitIdentical) {
  // Big, dense, strongly tilted lanterns seen from above, the moon low in view, thick fog and a
  // late TIME (wrapped phases).
  FrameContext ctx =
      context(Quality::Final, 5000.25, CameraPose{{0.0, 6.0, -12.0}, {0.0, -1.0, 0.0}, 60.0, 0.0});
  ctx.params.set("lantern_scale", {2.5});
  ctx.params.set("grid_size", {3.0});
  ctx.params.set("wave_amplitude", {0.5});
  ctx.params.set("flicker_strength", {2.0});
  ctx.params.set("fog_density", {0.05});
  ctx.params.set("moon_elevation", {20.0});
  expect_identical(ctx, "extremes from above");
  // Looking up at the moon from the water line.
  ctx.pose = CameraPose{{0.0, 0.2, 0.0}, {0.0, 0.6, 10.0}, 60.0, 0.0};
  finish_frame_context(ctx);
  ctx.params.set("moon_azimuth", {0.0});
  ctx.params.set("moon_elevation", {2.0});
  expect_identical(ctx, "moon at the horizon");
}

}  // namespace
}  // namespace sdfreel
