// water_lily's eight-lane geometry gives the scalar bits: the lane atan2 and mod, and the scene's
// distance functions at random points around the pond, at every preset's settings.
#include "scenes/water_lily/lanes.h"

#include <gtest/gtest.h>

#include <cstring>
#include <random>
#include <vector>

#include "render/frame_context.h"
#include "scenes/registry.h"
#include "scenes/water_lily/lanes_math.h"

namespace sdfreel::water_lily {
namespace {

bool same_bits(float a, float b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

TEST(WaterLilyLanes, Atan2AndModMatchTheScalarFunctions) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> unit(-3.0f, 3.0f);
  std::vector<float> special = {0.0f, -0.0f, 1.0f, -1.0f, 1e-30f, -1e-30f, 0.41421356f, 1e6f};
  for (int k = 0; k < 20000; ++k) {
    F8 y, x;
    for (int i = 0; i < LANES; ++i) {
      y[i] = k < 64 ? special[size_t(i) % special.size()] : unit(rng);
      x[i] = k < 64 ? special[size_t(k) % special.size()] : unit(rng);
    }
    const F8 a = dm::atan2(y, x);
    const F8 m = dm::mod(y, 0.785398f);
    for (int i = 0; i < LANES; ++i) {
      ASSERT_TRUE(same_bits(a[i], dm::atan2(y[i], x[i]))) << y[i] << " " << x[i];
      ASSERT_TRUE(same_bits(m[i], dm::mod(y[i], 0.785398f))) << y[i];
    }
  }
}

TEST(WaterLilyLanes, DistanceFunctionsMatchTheScalarPathAtEveryPreset) {
  const SceneInfo* info = find_scene("water_lily");
  ASSERT_NE(info, nullptr);
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
  constexpr int N = 4096;
  std::vector<float> x(N), y(N), z(N);
  for (int i = 0; i < N; ++i) {
    // Around the flowers and pads, some points inside them.
    x[i] = 0.15f + 2.5f * unit(rng) * (i % 2 ? 1.0f : 0.3f);
    y[i] = 0.2f + 0.25f * unit(rng);
    z[i] = 2.5f + 2.5f * unit(rng);
  }
  for (Quality q : {Quality::Draft, Quality::Final, Quality::Reference})
    for (bool naive : {false, true}) {
      FrameContext ctx;
      ctx.scene_time = 1.7;
      ctx.quality = q;
      ctx.pose = info->default_camera;
      ctx.params = ParamValues(&info->params);
      finish_frame_context(ctx);
      if (naive) ctx.march = naive_march_settings();
      const LilyUniforms u = make_lily_uniforms(ctx);
      for (const DistanceFunction& f : lilyDistanceFunctions(u)) {
        std::vector<float> a(N), b(N);
        f.scalar(x.data(), y.data(), z.data(), a.data(), N);
        f.lanes(x.data(), y.data(), z.data(), b.data(), N);
        int negative = 0;
        for (int i = 0; i < N; ++i) {
          ASSERT_TRUE(same_bits(a[i], b[i])) << f.name << " point " << i;
          negative += a[i] < 0.0f;
        }
        EXPECT_GT(negative, 0) << f.name;  // the points reach inside the parts
      }
    }
}

}  // namespace
}  // namespace sdfreel::water_lily
