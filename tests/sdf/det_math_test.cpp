// Deterministic math against libm (in double) over dense sweeps, plus special values. The bounds
// here are the ones documented in det_math.h.
#include "sdf/det_math.h"

#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <cstdint>
#include <functional>

namespace sdfreel {
namespace {

constexpr int SWEEP = 2000000;

// Largest |f(x) - ref(x)| over n evenly spaced floats in [lo, hi] (offset so that the sweep does
// not sit on round numbers only). Fails on any non-finite result.
double max_abs_error(const std::function<float(float)>& f, const std::function<double(double)>& ref,
                     double lo, double hi, int n = SWEEP) {
  double worst = 0.0;
  for (int i = 0; i < n; ++i) {
    const float x = float(lo + (hi - lo) * (double(i) + 0.318) / double(n));
    const float got = f(x);
    EXPECT_TRUE(std::isfinite(got)) << "x = " << x;
    if (!std::isfinite(got)) return INFINITY;
    worst = std::max(worst, std::abs(double(got) - ref(double(x))));
  }
  return worst;
}

double max_rel_error(const std::function<float(float)>& f, const std::function<double(double)>& ref,
                     double lo, double hi, int n = SWEEP) {
  double worst = 0.0;
  for (int i = 0; i < n; ++i) {
    const float x = float(lo + (hi - lo) * (double(i) + 0.318) / double(n));
    const float got = f(x);
    EXPECT_TRUE(std::isfinite(got)) << "x = " << x;
    if (!std::isfinite(got)) return INFINITY;
    const double r = ref(double(x));
    worst = std::max(worst, std::abs(double(got) - r) / std::abs(r));
  }
  return worst;
}

TEST(DetMath, SinCosAccurateToTenThousand) {
  EXPECT_LT(max_abs_error(
                dm::sin, [](double x) { return std::sin(x); }, -1e4, 1e4),
            2e-7);
  EXPECT_LT(max_abs_error(
                dm::cos, [](double x) { return std::cos(x); }, -1e4, 1e4),
            2e-7);
}

TEST(DetMath, SinCosAccurateToHundredThousand) {
  EXPECT_LT(max_abs_error(
                dm::sin, [](double x) { return std::sin(x); }, -1e5, 1e5),
            2e-7);
  EXPECT_LT(max_abs_error(
                dm::cos, [](double x) { return std::cos(x); }, -1e5, 1e5),
            2e-7);
}

TEST(DetMath, SinCosNearZeroAndQuadrantEdges) {
  EXPECT_LT(max_abs_error(
                dm::sin, [](double x) { return std::sin(x); }, -7.0, 7.0),
            1.5e-7);
  EXPECT_EQ(dm::sin(0.0f), 0.0f);
  EXPECT_EQ(dm::cos(0.0f), 1.0f);
  const float denormal = 1e-40f;
  EXPECT_EQ(dm::sin(denormal), denormal);  // sin x = x below float resolution
  EXPECT_EQ(dm::cos(denormal), 1.0f);
  EXPECT_NEAR(dm::sin(dm::HALF_PI), 1.0f, 1e-7f);
  EXPECT_NEAR(dm::cos(dm::PI), -1.0f, 1e-7f);
  // Relative accuracy for small arguments (sin x ~ x), which absolute bounds would not see.
  for (float x = 1e-30f; x < 1e-2f; x *= 1.37f)
    EXPECT_NEAR(dm::sin(x) / x, std::sin(double(x)) / double(x), 2e-7) << x;
}

TEST(DetMath, SinCosFiniteAndBoundedForHugeArguments) {
  for (float x : {1e6f, -3e7f, 1e20f, -1e30f, FLT_MAX, -FLT_MAX}) {
    EXPECT_TRUE(std::isfinite(dm::sin(x))) << x;
    EXPECT_LE(std::abs(dm::sin(x)), 1.0f) << x;
    EXPECT_TRUE(std::isfinite(dm::cos(x))) << x;
    EXPECT_LE(std::abs(dm::cos(x)), 1.0f) << x;
  }
}

TEST(DetMath, Atan2OverAllAnglesAndScales) {
  double worst = 0.0;
  const int n_angles = 20000, n_radii = 60;
  for (int j = 0; j < n_radii; ++j) {
    const double radius = std::pow(10.0, -30.0 + 60.0 * j / (n_radii - 1));
    for (int i = 0; i < n_angles; ++i) {
      const double theta = -M_PI + 2.0 * M_PI * (i + 0.5) / n_angles;
      const float y = float(radius * std::sin(theta)), x = float(radius * std::cos(theta));
      const float got = dm::atan2(y, x);
      ASSERT_TRUE(std::isfinite(got));
      worst = std::max(worst, std::abs(double(got) - std::atan2(double(y), double(x))));
    }
  }
  EXPECT_LT(worst, 3e-7);
}

TEST(DetMath, Atan2SpecialValues) {
  EXPECT_EQ(dm::atan2(0.0f, 0.0f), 0.0f);
  EXPECT_EQ(dm::atan2(-0.0f, -0.0f), 0.0f);
  EXPECT_NEAR(dm::atan2(0.0f, -1.0f), M_PI, 1e-7);
  EXPECT_NEAR(dm::atan2(1.0f, 0.0f), M_PI / 2, 1e-7);
  EXPECT_NEAR(dm::atan2(-1.0f, 0.0f), -M_PI / 2, 1e-7);
  EXPECT_NEAR(dm::atan2(1e-40f, 1e-40f), M_PI / 4, 1e-7);  // denormals
  EXPECT_NEAR(dm::atan2(FLT_MAX, 1e-30f), M_PI / 2, 1e-7);
  EXPECT_NEAR(dm::atan2(-FLT_MAX, -FLT_MAX), -3 * M_PI / 4, 1e-7);
}

TEST(DetMath, AtanSingleArgument) {
  EXPECT_LT(max_abs_error(
                dm::atan, [](double x) { return std::atan(x); }, -1e3, 1e3),
            3e-7);
  EXPECT_LT(max_abs_error(
                dm::atan, [](double x) { return std::atan(x); }, -2.0, 2.0),
            3e-7);
}

TEST(DetMath, AsinAcos) {
  EXPECT_LT(max_abs_error(
                dm::asin, [](double x) { return std::asin(x); }, -1.0, 1.0),
            4e-7);
  EXPECT_LT(max_abs_error(
                dm::acos, [](double x) { return std::acos(x); }, -1.0, 1.0),
            4e-7);
  EXPECT_EQ(dm::acos(1.0f), 0.0f);
  EXPECT_NEAR(dm::acos(-1.0f), M_PI, 1e-7);
  EXPECT_NEAR(dm::asin(1.0f), M_PI / 2, 1e-7);
  // |x| > 1 is clamped (rounding pushes dot products of unit vectors there).
  EXPECT_EQ(dm::acos(1.0000001f), 0.0f);
  EXPECT_NEAR(dm::acos(-3.0f), M_PI, 1e-7);
  EXPECT_NEAR(dm::asin(7.0f), M_PI / 2, 1e-7);
  EXPECT_NEAR(dm::asin(-FLT_MAX), -M_PI / 2, 1e-7);
}

TEST(DetMath, ExpRelativeError) {
  EXPECT_LT(max_rel_error(
                dm::exp, [](double x) { return std::exp(x); }, -87.3, 88.7),
            3e-7);
  EXPECT_LT(max_rel_error(
                dm::exp, [](double x) { return std::exp(x); }, -1.0, 1.0),
            2e-7);
  EXPECT_EQ(dm::exp(0.0f), 1.0f);
  EXPECT_EQ(dm::exp(-100.0f), 0.0f);
  EXPECT_EQ(dm::exp(-FLT_MAX), 0.0f);
  EXPECT_TRUE(std::isfinite(dm::exp(100.0f)));
  EXPECT_TRUE(std::isfinite(dm::exp(FLT_MAX)));
  EXPECT_GT(dm::exp(FLT_MAX), 1e38f);
  EXPECT_EQ(dm::exp(1e-40f), 1.0f);
}

TEST(DetMath, LogOverEveryBinade) {
  // Every exponent, denormals included: step through the bit patterns of positive floats.
  double worst = 0.0;
  const uint32_t last = 0x7f7fffffu;  // FLT_MAX
  const uint32_t stride = last / SWEEP;
  for (uint32_t bits = 1; bits <= last - stride; bits += stride) {
    const float x = dm::bits_float(bits + 12345u % stride);
    const float got = dm::log(x);
    ASSERT_TRUE(std::isfinite(got)) << x;
    const double ref = std::log(double(x));
    worst = std::max(worst, std::abs(double(got) - ref) / std::max(1.0, std::abs(ref)));
  }
  EXPECT_LT(worst, 1.5e-7);
  // Near 1, where log -> 0, absolute error is what matters.
  EXPECT_LT(max_abs_error(
                dm::log, [](double x) { return std::log(x); }, 0.5, 2.0),
            1e-7);
  EXPECT_LT(max_rel_error(
                dm::log, [](double x) { return std::log(x); }, 2.0, 1e6),
            3e-7);
}

TEST(DetMath, LogSpecialValues) {
  EXPECT_EQ(dm::log(1.0f), 0.0f);
  EXPECT_EQ(dm::log(0.0f), -FLT_MAX);
  EXPECT_EQ(dm::log(-1.0f), -FLT_MAX);
  EXPECT_EQ(dm::log(NAN), -FLT_MAX);
  EXPECT_NEAR(dm::log(INFINITY), std::log(double(FLT_MAX)), 1e-5);
  EXPECT_NEAR(dm::log(1e-45f), std::log(double(1e-45f)), 2e-5);  // smallest denormal
  EXPECT_EQ(dm::exp(dm::log(0.0f)), 0.0f);
}

TEST(DetMath, PowRelativeError) {
  // |y ln x| up to 80: the error of y * log(x) is amplified by exp, so the bound grows with it.
  double worst = 0.0, worst_moderate = 0.0, worst_large = 0.0;
  const int nx = 2000, ny = 600;
  for (int i = 0; i < nx; ++i) {
    const float x = float(std::pow(10.0, -6.0 + 12.0 * (i + 0.37) / nx));
    for (int j = 0; j < ny; ++j) {
      const float y = float(-6.0 + 12.0 * (j + 0.41) / ny);
      const double ref = std::pow(double(x), double(y));
      if (ref > 1e37 || ref < 1e-37) continue;
      const float got = dm::pow(x, y);
      ASSERT_TRUE(std::isfinite(got)) << x << " " << y;
      const double rel = std::abs(double(got) - ref) / ref;
      const double amplification = std::abs(double(y) * std::log(double(x)));
      worst = std::max(worst, rel / (1.0 + amplification));
      if (amplification < 10.0) worst_moderate = std::max(worst_moderate, rel);
      if (amplification < 60.0) worst_large = std::max(worst_large, rel);
    }
  }
  EXPECT_LT(worst, 1.5e-7);           // rel <= 1.5e-7 * (1 + |y ln x|)
  EXPECT_LT(worst_moderate, 1.5e-6);  // so under 1.5e-6 when |y ln x| < 10
  EXPECT_LT(worst_large, 1e-5);       // and under 1e-5 when |y ln x| < 60
}

TEST(DetMath, PowSpecialValues) {
  EXPECT_EQ(dm::pow(0.0f, 2.5f), 0.0f);
  EXPECT_EQ(dm::pow(-0.0f, 2.5f), 0.0f);
  EXPECT_EQ(dm::pow(0.0f, 0.0f), 1.0f);
  EXPECT_EQ(dm::pow(0.0f, -1.0f), FLT_MAX);
  EXPECT_EQ(dm::pow(-2.0f, 2.0f), 0.0f);  // negative base counts as 0, documented
  EXPECT_EQ(dm::pow(1.0f, 123.0f), 1.0f);
  EXPECT_EQ(dm::pow(3.7f, 0.0f), 1.0f);
  EXPECT_TRUE(std::isfinite(dm::pow(FLT_MAX, 2.0f)));
  EXPECT_EQ(dm::pow(1e-30f, 5.0f), 0.0f);
  EXPECT_NEAR(dm::pow(2.0f, 10.0f), 1024.0f, 1024.0f * 2e-6f);
}

TEST(DetMath, Tanh) {
  EXPECT_LT(max_abs_error(
                dm::tanh, [](double x) { return std::tanh(x); }, -20.0, 20.0),
            3e-7);
  EXPECT_LT(max_abs_error(
                dm::tanh, [](double x) { return std::tanh(x); }, -1.0, 1.0),
            2e-7);
  EXPECT_EQ(dm::tanh(0.0f), 0.0f);
  EXPECT_EQ(dm::tanh(1e4f), 1.0f);
  EXPECT_EQ(dm::tanh(-FLT_MAX), -1.0f);
  for (float x = 1e-30f; x < 0.5f; x *= 1.5f)
    EXPECT_NEAR(dm::tanh(x) / x, std::tanh(double(x)) / double(x), 2e-7) << x;
}

TEST(DetMath, GlslHelpers) {
  EXPECT_EQ(dm::fract(2.25f), 0.25f);
  EXPECT_EQ(dm::fract(-0.25f), 0.75f);
  EXPECT_EQ(dm::mod(-1.0f, 3.0f), 2.0f);  // GLSL mod takes the sign of y, unlike fmod
  EXPECT_EQ(dm::mod(7.5f, 2.0f), 1.5f);
  EXPECT_EQ(dm::clamp(5.0f, 0.0f, 1.0f), 1.0f);
  EXPECT_EQ(dm::clamp(-5.0f, 0.0f, 1.0f), 0.0f);
  EXPECT_EQ(dm::mix(3.0f, 7.0f, 0.0f), 3.0f);
  EXPECT_EQ(dm::mix(3.0f, 7.0f, 1.0f), 7.0f);
  EXPECT_EQ(dm::mix(3.0f, 7.0f, 0.5f), 5.0f);
  EXPECT_EQ(dm::smoothstep(0.0f, 1.0f, -1.0f), 0.0f);
  EXPECT_EQ(dm::smoothstep(0.0f, 1.0f, 2.0f), 1.0f);
  EXPECT_EQ(dm::smoothstep(0.0f, 1.0f, 0.5f), 0.5f);
  EXPECT_EQ(dm::smoothstep(1.0f, 0.0f, 0.25f), 0.84375f);  // reversed edges, like GLSL
  EXPECT_EQ(dm::smoothstep(1.0f, 1.0f, 0.5f), 0.0f);       // degenerate edges: a step, not NaN
  EXPECT_EQ(dm::smoothstep(1.0f, 1.0f, 1.5f), 1.0f);
  EXPECT_EQ(dm::sqrt(2.0f), std::sqrt(2.0f));
}

TEST(DetMath, WrapPhaseKeepsLargeTimesPrecise) {
  EXPECT_NEAR(dm::wrap_phase(1e6 + 0.25, 1.0), 0.25f, 1e-7f);
  EXPECT_NEAR(dm::wrap_phase(1e6 + 1.0 / 30.0, 2.0), float(1.0 / 30.0), 1e-7f);
  EXPECT_NEAR(dm::wrap_phase(-0.5, 2.0), 1.5f, 1e-7f);
  EXPECT_NEAR(dm::wrap_phase(1e9 * 0.4, 2.0 * M_PI), float(std::fmod(4e8, 2.0 * M_PI)), 1e-6f);
  EXPECT_EQ(dm::wrap_phase(3.0, 3.0), 0.0f);
  EXPECT_EQ(dm::wrap_phase(-1e-20, 1.0), 0.0f);  // 1 - 1e-20 rounds to the period itself
  EXPECT_EQ(dm::wrap_phase(INFINITY, 1.0), 0.0f);
  EXPECT_EQ(dm::wrap_phase(NAN, 1.0), 0.0f);
  EXPECT_EQ(dm::wrap_phase(5.0, 0.0), 0.0f);
  for (int i = 0; i < 100000; ++i) {
    const double x = (i - 50000) * 12345.6789 + i * 1e-3;
    const double period = 0.1 + (i % 97) * 0.37;
    const float w = dm::wrap_phase(x, period);
    ASSERT_GE(w, 0.0f);
    ASSERT_LT(w, float(period));
  }
}

}  // namespace
}  // namespace sdfreel
