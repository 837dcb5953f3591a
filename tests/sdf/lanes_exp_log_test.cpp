// exp, log, pow, atan2, asin and acos on lanes (sdf/lanes_exp_log.h) give, in every lane, the bits
// of the scalar functions of det_math.h: wide sweeps, every power of two, and the awkward inputs
// (zeros of both signs, denormals, the largest floats, infinities, NaN).
#include "sdf/lanes_exp_log.h"

#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

namespace sdfreel {
namespace {

bool same_bits(float a, float b) {
  return std::memcmp(&a, &b, sizeof a) == 0 || (std::isnan(a) && std::isnan(b));
}

std::vector<float> awkward() {
  const float inf = std::numeric_limits<float>::infinity();
  std::vector<float> xs = {0.0f,    -0.0f,    FLT_MIN,  -FLT_MIN,   FLT_TRUE_MIN, 1e-40f,
                           FLT_MAX, -FLT_MAX, inf,      -inf,       NAN,          1.0f,
                           -1.0f,   88.72f,   88.7228f, 88.73f,     -87.33f,      -87.34f,
                           -104.0f, 1e30f,    -1e30f,   0.7071067f, 0.7071068f};
  for (int e = -149; e <= 127; ++e) xs.push_back(std::ldexp(1.0f, e));
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> exponent(-40.0f, 40.0f), sign(-1.0f, 1.0f);
  for (int i = 0; i < 200000; ++i) xs.push_back(std::copysign(std::exp2(exponent(rng)), sign(rng)));
  for (int i = 0; i < 200000; ++i) xs.push_back(120.0f * sign(rng));
  while (xs.size() % LANES) xs.push_back(0.5f);
  return xs;
}

template <class LaneFn, class ScalarFn>
int mismatches(const std::vector<float>& xs, LaneFn lane_fn, ScalarFn scalar_fn) {
  int bad = 0;
  for (size_t i = 0; i + LANES <= xs.size(); i += LANES) {
    const F8 r = lane_fn(load8(&xs[i]));
    for (int k = 0; k < LANES; ++k)
      if (!same_bits(r[k], scalar_fn(xs[i + k]))) ++bad;
  }
  return bad;
}

TEST(LanesExpLog, ExpAndLogMatchScalarBits) {
  const std::vector<float> xs = awkward();
  EXPECT_EQ(mismatches(
                xs, [](F8 v) { return dm::exp(v); }, [](float x) { return dm::exp(x); }),
            0);
  EXPECT_EQ(mismatches(
                xs, [](F8 v) { return dm::log(v); }, [](float x) { return dm::log(x); }),
            0);
}

TEST(LanesExpLog, PowWithAUniformExponentMatchesScalarBits) {
  const std::vector<float> xs = awkward();
  for (float y : {1.0f / 2.4f, 0.9811f - 1.0f, 2.2f, 0.0f, -3.0f, 40.0f})
    EXPECT_EQ(mismatches(
                  xs, [y](F8 v) { return dm::pow(v, y); }, [y](float x) { return dm::pow(x, y); }),
              0)
        << "exponent " << y;
}

TEST(LanesExpLog, Atan2MatchesScalarBitsInEveryQuadrant) {
  const std::vector<float> ys = awkward();
  std::vector<float> xs(ys.rbegin(), ys.rend());  // a different partner for every y
  int bad = 0;
  for (size_t i = 0; i + LANES <= ys.size(); i += LANES) {
    const F8 r = dm::atan2(load8(&ys[i]), load8(&xs[i]));
    for (int k = 0; k < LANES; ++k)
      if (!same_bits(r[k], dm::atan2(ys[i + k], xs[i + k]))) ++bad;
  }
  EXPECT_EQ(bad, 0);
  // Both zeros, axes and diagonals.
  const F8 y{0.0f, -0.0f, 1.0f, -1.0f, 0.0f, 2.0f, -2.0f, 1e-30f};
  const F8 x{0.0f, 0.0f, 0.0f, 0.0f, -1.0f, 2.0f, -2.0f, -1e30f};
  const F8 r = dm::atan2(y, x);
  for (int k = 0; k < LANES; ++k) EXPECT_TRUE(same_bits(r[k], dm::atan2(y[k], x[k]))) << k;
}

TEST(LanesExpLog, AsinAndAcosMatchScalarBitsInsideAndOutsideTheirDomain) {
  std::vector<float> xs = awkward();
  // Every float step round the branch points -1, -0.5, 0, 0.5 and 1, and a sweep of
  // [-1.25, 1.25].
  for (float edge : {-1.0f, -0.5f, 0.0f, 0.5f, 1.0f}) {
    float v = edge;
    for (int i = 0; i < 64; ++i) v = std::nextafter(v, -2.0f);
    for (int i = 0; i < 128; ++i, v = std::nextafter(v, 2.0f)) xs.push_back(v);
  }
  for (int i = 0; i <= 200000; ++i) xs.push_back(-1.25f + 2.5f * float(i) / 200000.0f);
  while (xs.size() % LANES) xs.push_back(0.0f);
  EXPECT_EQ(mismatches(
                xs, [](F8 v) { return dm::acos(v); }, [](float x) { return dm::acos(x); }),
            0);
  EXPECT_EQ(mismatches(
                xs, [](F8 v) { return dm::asin(v); }, [](float x) { return dm::asin(x); }),
            0);
}

TEST(LanesExpLog, GatherLoadsEachLanesEntry) {
  const float table[10] = {0.5f, 1.5f, 2.5f, 3.5f, 4.5f, 5.5f, 6.5f, 7.5f, 8.5f, 9.5f};
  const F8 g = gather(table, M8{9, 0, 3, 3, 7, 1, 8, 2});
  const int want[LANES] = {9, 0, 3, 3, 7, 1, 8, 2};
  for (int k = 0; k < LANES; ++k) EXPECT_EQ(g[k], table[want[k]]);
}

}  // namespace
}  // namespace sdfreel
