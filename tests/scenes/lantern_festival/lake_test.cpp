// The lake: its Lipschitz bound really bounds the slopes, the march never passes through the
// surface, and TIME = 1e6 s still animates smoothly.
#include "scenes/lantern_festival/lake.h"

#include <gtest/gtest.h>

#include <cmath>

#include "scenes/lantern_festival/march.h"
#include "sdf/noise.h"

namespace sdfreel::lantern_festival {
namespace {

float unit(uint32_t& state) {
  state = pcg_hash(state);
  return hash_to_unit(state);
}

TEST(LanternFestivalLake, SeedWaveConstants) {
  const LakeFrame k = make_lake_frame(0.0, 0.15f, 2.5f);
  EXPECT_FLOAT_EQ(k.amp[0], 0.09f);   // 0.15 * 0.6 before the first wave
  EXPECT_FLOAT_EQ(k.freq[0], 0.56f);  // 0.4 * 1.4
  EXPECT_NEAR(k.amp[4], 0.15 * std::pow(0.6, 5), 1e-7);
  EXPECT_NEAR(k.freq[4], 0.4 * std::pow(1.4, 5), 1e-5);
  EXPECT_FLOAT_EQ(k.rough_amp, 0.15f);
  EXPECT_FLOAT_EQ(k.rough_freq, 0.4f);
  // The rough wave lags by 0.2 s of TIME: at TIME = 0 its phase is -0.5 rad, wrapped.
  EXPECT_NEAR(k.rough_phase, 2.0 * M_PI - 0.5, 1e-6);
}

TEST(LanternFestivalLake, SampledSlopesNeverExceedTheLipschitzBound) {
  for (float amplitude : {0.05f, 0.15f, 0.5f})
    for (double time : {0.0, 3.3, 1e6 + 0.25}) {
      const LakeFrame k = make_lake_frame(time, amplitude, 2.5f);
      uint32_t s = 17u;
      double worst_analytic = 0.0, worst_sampled = 0.0;
      const float h = 1e-2f;
      for (int i = 0; i < 50000; ++i) {
        const glm::vec2 p((unit(s) - 0.5f) * 200.0f, (unit(s) - 0.5f) * 200.0f);
        worst_analytic = std::max(worst_analytic, double(glm::length(waterHeightGradientAt(k, p))));
        // Finite differences in every direction: |h(p + d) - h(p)| / |d| <= L.
        const float a = unit(s) * dm::TWO_PI;
        const glm::vec2 d(h * std::cos(a), h * std::sin(a));
        const double slope =
            std::fabs(double(waterHeightAt(k, p + d)) - double(waterHeightAt(k, p))) / h;
        worst_sampled = std::max(worst_sampled, slope);
      }
      EXPECT_LE(worst_analytic, k.lipschitz);
      EXPECT_LE(worst_sampled, k.lipschitz);
      // The bound is not loose by orders of magnitude (it is the sum of amplitude * frequency).
      EXPECT_GT(worst_analytic, 0.5 * k.lipschitz);
      // And the gradient of sdfWater, (hx, 1, hz), is bounded by 1 / step_scale.
      EXPECT_LE(std::sqrt(1.0 + worst_analytic * worst_analytic), 1.0 / k.step_scale);
    }
}

TEST(LanternFestivalLake, MarchNeverOvershootsTheSurface) {
  const LakeFrame k = make_lake_frame(7.0, 0.5f, 2.5f);  // the steepest allowed waves
  for (float step_factor : {1.0f, 1.2f, 1.9f}) {  // plain, the presets' over-relaxation, extreme
    MarchLimits lim;
    lim.max_steps = 1024;
    lim.hit_eps = 0.25f;
    lim.pixel_angle = 2e-3f;
    lim.step_factor = step_factor;
    uint32_t s = 23u;
    int hits = 0;
    for (int i = 0; i < 1000; ++i) {
      const glm::vec3 o((unit(s) - 0.5f) * 50.0f, 0.2f + unit(s) * 3.0f, (unit(s) - 0.5f) * 50.0f);
      const float az = unit(s) * dm::TWO_PI, el = -0.02f - unit(s) * 0.8f;
      const glm::vec3 dir = glm::normalize(
          glm::vec3(std::cos(az) * std::cos(el), std::sin(el), std::sin(az) * std::cos(el)));
      RayStats st;
      const MarchHit hit = marchWater(k, o, dir, 200.0f, lim, st);
      if (!hit.hit) continue;
      ++hits;
      // Everything before the hit is above the water (up to the hit tolerance at the end).
      for (float t = 0.0f; t < hit.t; t += 0.02f)
        ASSERT_GT(sdfWater(k, o + dir * t), -1e-4f)
            << "ray " << i << " step factor " << step_factor;
      EXPECT_LT(std::fabs(sdfWater(k, o + dir * hit.t)), lim.eps_at(hit.t) + 1e-6f);
    }
    EXPECT_GT(hits, 800);
  }
}

TEST(LanternFestivalLake, RaysGoingUpNeverHit) {
  const LakeFrame k = make_lake_frame(1.0, 0.15f, 2.5f);
  MarchLimits lim;
  RayStats st;
  EXPECT_FALSE(marchWater(k, glm::vec3(0.0f, 1.0f, 0.0f),
                          glm::normalize(glm::vec3(1.0f, 0.01f, 0.0f)), 500.0f, lim, st)
                   .hit);
  EXPECT_EQ(st.capped, 0u);
}

// TIME = 1e6 s: consecutive frames (1/30 s) move the water by a small, non-zero amount, as at
// TIME = 0. Without wrapping in double, float TIME would move in steps of 0.0625 s or freeze.
TEST(LanternFestivalLake, HugeTimeAnimatesSmoothly) {
  const glm::vec2 p(3.0f, -2.0f);
  for (double base : {0.0, 1e6}) {
    int moved = 0;
    for (int f = 0; f < 30; ++f) {
      const LakeFrame a = make_lake_frame(base + f / 30.0, 0.15f, 2.5f);
      const LakeFrame b = make_lake_frame(base + (f + 1) / 30.0, 0.15f, 2.5f);
      const float dh = std::fabs(waterHeightAt(b, p) - waterHeightAt(a, p));
      // |dh/dt| <= sum(amp) * speed: at most 0.207 * 2.5 / 30 per frame.
      EXPECT_LE(dh, a.max_height * 2.5f / 30.0f + 1e-5f);
      moved += dh > 1e-5f;
    }
    EXPECT_GE(moved, 27) << "TIME base " << base;
  }
}

TEST(LanternFestivalLake, RoughNormalIsUnitAndTilted) {
  const LakeFrame k = make_lake_frame(0.4, 0.15f, 2.5f);
  float max_tilt = 0.0f;
  for (float x = -20.0f; x <= 20.0f; x += 0.5f) {
    const glm::vec3 n = normalWaterRough(k, glm::vec2(x, 0.7f * x));
    EXPECT_NEAR(glm::length(n), 1.0f, 1e-5f);
    EXPECT_GT(n.y, 0.99f);
    max_tilt = std::max(max_tilt, std::sqrt(n.x * n.x + n.z * n.z));
  }
  EXPECT_GT(max_tilt, 0.03f);  // 0.15 * 0.4 = 0.06 at the steepest point
}

}  // namespace
}  // namespace sdfreel::lantern_festival
