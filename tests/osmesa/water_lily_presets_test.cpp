// water_lily in process, on both backends: the GLSL twin (shaders/water_lily/) computes the same
// linear floats as the C++ scene, bit for bit, and the same SDF evaluation count, for every march
// preset and mode (draft, final, reference, naive, hit mask) and at parameter extremes. A
// mismatch names the first pixels.
#include <gtest/gtest.h>

#include <cstring>
#include <memory>

#include "backends/cpu/cpu_backend.h"
#include "backends/osmesa/osmesa_backend.h"
#include "scenes/registry.h"

namespace sdfreel {
namespace {

constexpr int W = 64, H = 36;

const SceneInfo& lily_info() {
  const SceneInfo* s = find_scene("water_lily");
  if (!s) throw std::runtime_error("water_lily is not registered");
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
  ctx.params = ParamValues(&lily_info().params);
  finish_frame_context(ctx);
  return ctx;
}

// Low between the flowers, as the flythrough.
CameraPose corridor() {
  return CameraPose{{0.9, 0.35, -0.9}, {0.15, 0.2, 1.3}, 50.0, 0.0};
}

class WaterLilyPresets : public ::testing::Test {
 protected:
  void SetUp() override {
    try {
      osmesa = std::make_unique<OsmesaBackend>();
    } catch (const std::exception& e) {
      GTEST_SKIP() << "OSMesa unavailable: " << e.what();
    }
    osmesa->begin(lily_info());
    cpu.begin(lily_info());
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

TEST_F(WaterLilyPresets, QualityPresetsAreBitIdentical) {
  for (Quality q : {Quality::Draft, Quality::Final, Quality::Reference})
    expect_identical(context(q, 3.0, corridor()), quality_name(q));
}

TEST_F(WaterLilyPresets, NaivePresetAndHitMaskAreBitIdentical) {
  FrameContext naive = context(Quality::Final, 3.0, corridor());
  naive.march = naive_march_settings();
  expect_identical(naive, "naive");
  naive.march.hit_mask = true;
  expect_identical(naive, "naive hit mask");
  // The default view, the bench's: long naive marches over the pond.
  FrameContext wide = context(Quality::Final, 0.0, lily_info().default_camera);
  wide.march = naive_march_settings();
  expect_identical(wide, "naive, default view");
  FrameContext mask = context(Quality::Final, 3.0, corridor());
  mask.march.hit_mask = true;
  expect_identical(mask, "final hit mask");
}

TEST_F(WaterLilyPresets, ParameterExtremesAreBitIdentical) {
  // Tight curls, a far drift, a fast rough mirror at the wrap of its time axis, a low sun
  // behind the flowers, hard shadows, full grading, seen from above.
  FrameContext ctx =
      context(Quality::Final, 1462.0, CameraPose{{0.6, 1.6, -0.5}, {0.3, 0.0, 2.5}, 60.0, 0.0});
  ctx.params.set("curl_amount", {1.6});
  ctx.params.set("leaf_drift", {1.0});
  ctx.params.set("water_speed", {0.35});
  ctx.params.set("water_bump", {4.0});
  ctx.params.set("sun_elevation", {8.0});
  ctx.params.set("sun_azimuth", {10.0});
  ctx.params.set("shadow_softness", {128.0});
  ctx.params.set("contrast", {1.0});
  ctx.params.set("saturation", {2.0});
  ctx.params.set("vignette", {2.0});
  expect_identical(ctx, "extremes from above");
}

}  // namespace
}  // namespace sdfreel
