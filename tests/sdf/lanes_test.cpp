// Lane functions (sdf/lanes.h) and the templated primitives (sdf/sdf.h) give, in every lane, the
// bits of the scalar functions: dense sweeps for sin/cos, seeded random points for primitives.
#include "sdf/lanes.h"

#include <gtest/gtest.h>

#include <array>
#include <cstring>
#include <random>
#include <vector>

#include "sdf/det_math.h"
#include "sdf/sdf.h"

namespace sdfreel {
namespace {

bool same_bits(float a, float b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

// Runs f on 8 lanes and on each value alone; counts lanes whose bits differ.
template <class LaneFn, class ScalarFn>
int mismatches(const std::vector<float>& xs, LaneFn lane_fn, ScalarFn scalar_fn) {
  int bad = 0;
  for (size_t i = 0; i + LANES <= xs.size(); i += LANES) {
    const F8 v = load8(&xs[i]);
    const F8 r = lane_fn(v);
    for (int k = 0; k < LANES; ++k)
      if (!same_bits(r[k], scalar_fn(xs[i + k]))) ++bad;
  }
  return bad;
}

std::vector<float> sweep(float lo, float hi, int n) {
  std::vector<float> xs;
  for (int i = 0; i < n; ++i) xs.push_back(lo + (hi - lo) * float(i) / float(n - 1));
  // Quadrant boundaries and special values.
  for (float s : {0.0f, -0.0f, dm::HALF_PI, -dm::HALF_PI, dm::PI, 1e5f, -1e5f, 3e7f, 1e-30f})
    xs.push_back(s);
  while (xs.size() % LANES) xs.push_back(0.5f);
  return xs;
}

TEST(Lanes, SinAndCosMatchScalarBits) {
  const std::vector<float> xs = sweep(-2000.0f, 2000.0f, 400000);
  EXPECT_EQ(mismatches(
                xs, [](F8 v) { return dm::sin(v); }, [](float x) { return dm::sin(x); }),
            0);
  EXPECT_EQ(mismatches(
                xs, [](F8 v) { return dm::cos(v); }, [](float x) { return dm::cos(x); }),
            0);
}

TEST(Lanes, ElementaryFunctionsMatchScalarBits) {
  const std::vector<float> xs = sweep(-50.0f, 50.0f, 20000);
  EXPECT_EQ(mismatches(
                xs, [](F8 v) { return dm::floor(v); }, [](float x) { return dm::floor(x); }),
            0);
  EXPECT_EQ(mismatches(
                xs, [](F8 v) { return dm::sqrt(dm::abs(v)); },
                [](float x) { return dm::sqrt(dm::abs(x)); }),
            0);
  EXPECT_EQ(mismatches(
                xs, [](F8 v) { return dm::clamp(v, -3.0f, 7.0f); },
                [](float x) { return dm::clamp(x, -3.0f, 7.0f); }),
            0);
  EXPECT_EQ(mismatches(
                xs, [](F8 v) { return dm::smoothstep(-4.0f, 9.0f, v); },
                [](float x) { return dm::smoothstep(-4.0f, 9.0f, x); }),
            0);
  EXPECT_EQ(mismatches(
                xs, [](F8 v) { return dm::sign(v); }, [](float x) { return dm::sign(x); }),
            0);
  EXPECT_EQ(mismatches(
                xs, [](F8 v) { return dm::fract(v); }, [](float x) { return dm::fract(x); }),
            0);
}

// glm::abs keeps the sign of -0; the lane version must too (it feeds subtractions whose -0 or +0
// can decide a later comparison).
TEST(Lanes, VectorAbsKeepsGlmSignOfZero) {
  const V3x8 v(splat(-0.0f), splat(-1.0f), splat(2.0f));
  const glm::vec3 s = glm::abs(glm::vec3(-0.0f, -1.0f, 2.0f));
  const V3x8 a = vabs(v);
  EXPECT_TRUE(same_bits(a.x[3], s.x));
  EXPECT_TRUE(same_bits(a.y[3], s.y));
}

TEST(Lanes, AnyAllAndSelect) {
  M8 none = splat_mask(false), every = splat_mask(true);
  EXPECT_FALSE(any(none));
  EXPECT_TRUE(all(every));
  M8 one = none;
  one[5] = -1;
  EXPECT_TRUE(any(one));
  EXPECT_FALSE(all(one));
  EXPECT_EQ(count_lanes(one), 1u);
  EXPECT_EQ(count_lanes(every), 8u);
  EXPECT_EQ(count_lanes(none), 0u);
  const F8 s = select(one, splat(1.0f), splat(2.0f));
  EXPECT_EQ(s[5], 1.0f);
  EXPECT_EQ(s[4], 2.0f);
}

// Every templated primitive, for one point type: the same calls serve lanes and single points.
template <class V>
auto primitives(const V& p) {
  const glm::vec3 b(0.6f, 0.3f, 0.9f);
  using F = decltype(sdSphere(p, 0.7f));
  return std::array<F, 11>{
      sdSphere(p, 0.7f),
      sdBox(p, b),
      sdRoundBox(p, b, 0.1f),
      sdTorus(p, glm::vec2(0.8f, 0.2f)),
      sdCappedTorus(p, glm::vec2(0.866f, 0.5f), 0.7f, 0.1f),
      sdCappedCylinder(p, 0.9f, 0.4f),
      sdCappedCylinderOffset(p, 1.03f, 0.05f, glm::vec2(0.53f)),
      sdPlane(p, glm::vec3(0.0f, 1.0f, 0.0f), 1.0f),
      opSmoothUnion(sdTorus(p, glm::vec2(0.8f, 0.2f)), sdBox(p, b), 0.1f),
      opSubtraction(sdBox(p, b), opOnion(sdCappedCylinder(p, 0.9f, 0.4f), 0.03f)),
      sdBox(opSymXZ(rotateY(p, 0.8f, 0.6f)), b)};
}

// Lanes of random points against the glm call on each point.
TEST(Lanes, PrimitivesMatchScalarBits) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(-2.5f, 2.5f);
  int bad = 0, checked = 0;
  for (int rep = 0; rep < 4000; ++rep) {
    V3x8 p;
    for (int k = 0; k < LANES; ++k) p.set_lane(k, glm::vec3(u(rng), u(rng), u(rng)));
    // Exact zeros and axis points, where abs/sign/select choices matter.
    if (rep % 7 == 0) p.x = splat(0.0f);
    if (rep % 11 == 0) p.z = splat(-0.0f);
    const auto lanes = primitives(p);
    for (int k = 0; k < LANES; ++k) {
      const auto single = primitives(p.lane(k));
      for (size_t f = 0; f < single.size(); ++f) {
        ++checked;
        if (!same_bits(lanes[f][k], single[f])) ++bad;
      }
    }
  }
  EXPECT_GT(checked, 300000);
  EXPECT_EQ(bad, 0);
}

}  // namespace
}  // namespace sdfreel
