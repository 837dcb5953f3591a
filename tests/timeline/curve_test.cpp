#include "timeline/curve.h"

#include <gtest/gtest.h>

#include <cmath>

namespace sdfreel {
namespace {

Curve scalar_curve(Interp interp, std::vector<std::pair<double, double>> keys) {
  Curve c;
  c.interp = interp;
  for (auto [t, v] : keys) {
    c.t.push_back(t);
    c.values.push_back({v});
  }
  return c;
}

double at(const Curve& c, double t) {
  return c.sample(t)[0];
}

TEST(Curve, ParsesInterpolationNames) {
  EXPECT_EQ(parse_interp("step"), Interp::Step);
  EXPECT_EQ(parse_interp("linear"), Interp::Linear);
  EXPECT_EQ(parse_interp("smooth"), Interp::Smooth);
  EXPECT_EQ(parse_interp("catmull-rom"), Interp::CatmullRom);
  EXPECT_FALSE(parse_interp("cubic"));
  EXPECT_FALSE(parse_interp("Linear"));
}

TEST(Curve, StepHoldsThePreviousKey) {
  Curve c = scalar_curve(Interp::Step, {{0, 1}, {1, 3}, {2, 2}});
  EXPECT_EQ(at(c, 0.5), 1);
  EXPECT_EQ(at(c, 1.0), 3);
  EXPECT_EQ(at(c, 1.999), 3);
  EXPECT_EQ(at(c, 2.0), 2);
}

TEST(Curve, LinearInterpolatesEachComponent) {
  Curve c;
  c.interp = Interp::Linear;
  c.t = {0, 2};
  c.values = {{0, 10, -4}, {4, 20, 4}};
  EXPECT_EQ(c.sample(0.5), (std::vector<double>{1, 12.5, -2}));
  EXPECT_EQ(c.sample(1.0), (std::vector<double>{2, 15, 0}));
}

TEST(Curve, HoldsEndValuesOutsideTheKeys) {
  for (Interp mode : {Interp::Step, Interp::Linear, Interp::Smooth, Interp::CatmullRom}) {
    Curve c = scalar_curve(mode, {{1, 5}, {2, 7}, {4, -1}});
    EXPECT_EQ(at(c, -100), 5);
    EXPECT_EQ(at(c, 1), 5);
    EXPECT_EQ(at(c, 4), -1);
    EXPECT_EQ(at(c, 1e9), -1);
  }
}

TEST(Curve, SingleKeyIsConstant) {
  Curve c = scalar_curve(Interp::CatmullRom, {{3, 0.25}});
  EXPECT_EQ(at(c, 0), 0.25);
  EXPECT_EQ(at(c, 3), 0.25);
  EXPECT_EQ(at(c, 7), 0.25);
}

TEST(Curve, SmoothIsCubicHermiteWithFlatKeys) {
  Curve c = scalar_curve(Interp::Smooth, {{0, 1}, {2, 3}});
  EXPECT_DOUBLE_EQ(at(c, 1.0), 2.0);                                      // midpoint
  EXPECT_DOUBLE_EQ(at(c, 0.5), 1.0 + 2.0 * (3 * 0.0625 - 2 * 0.015625));  // s = 1/4
  // Zero slope at the keys: a tiny step away moves the value by O(step^2).
  EXPECT_NEAR(at(c, 1e-4), 1.0, 1e-7);
  EXPECT_NEAR(at(c, 2.0 - 1e-4), 3.0, 1e-7);
}

TEST(Curve, CatmullRomPassesThroughKeysAndKeepsLinesStraight) {
  // Equally spaced values on a line: the centripetal spline (with mirrored ends) is that line.
  Curve c = scalar_curve(Interp::CatmullRom, {{0, 0}, {1, 1}, {2, 2}, {3, 3}});
  for (double t : {0.0, 0.25, 0.5, 1.0, 1.5, 2.75, 3.0}) EXPECT_NEAR(at(c, t), t, 1e-12) << t;
}

// Uniform Catmull-Rom in matrix form: the centripetal spline equals it when neighbouring keys are
// equally far apart.
std::vector<double> uniform_catmull_rom(const std::vector<std::vector<double>>& p, double s) {
  std::vector<double> out;
  for (size_t i = 0; i < p[0].size(); ++i) {
    double p0 = p[0][i], p1 = p[1][i], p2 = p[2][i], p3 = p[3][i];
    out.push_back(0.5 * (2 * p1 + (-p0 + p2) * s + (2 * p0 - 5 * p1 + 4 * p2 - p3) * s * s +
                         (-p0 + 3 * p1 - 3 * p2 + p3) * s * s * s));
  }
  return out;
}

TEST(Curve, CatmullRomWithEqualSpacingMatchesUniformForm) {
  Curve c;
  c.interp = Interp::CatmullRom;
  c.t = {0, 1, 2, 3};
  c.values = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};  // unit steps around a square
  for (double s : {0.1, 0.5, 0.8}) {
    std::vector<double> got = c.sample(1 + s), want = uniform_catmull_rom(c.values, s);
    EXPECT_NEAR(got[0], want[0], 1e-12) << s;
    EXPECT_NEAR(got[1], want[1], 1e-12) << s;
  }
}

// Centripetal Catmull-Rom as a Hermite segment with the tangents of the non-uniform form
// (knot intervals sqrt(distance)): an independent formula for the same curve.
std::vector<double> centripetal_hermite(const std::vector<std::vector<double>>& p, double s) {
  auto dist = [](const std::vector<double>& a, const std::vector<double>& b) {
    double sum = 0;
    for (size_t i = 0; i < a.size(); ++i) sum += (b[i] - a[i]) * (b[i] - a[i]);
    return std::sqrt(sum);
  };
  double d0 = std::sqrt(dist(p[0], p[1])), d1 = std::sqrt(dist(p[1], p[2])),
         d2 = std::sqrt(dist(p[2], p[3]));
  double h00 = 2 * s * s * s - 3 * s * s + 1, h10 = s * s * s - 2 * s * s + s,
         h01 = -2 * s * s * s + 3 * s * s, h11 = s * s * s - s * s;
  std::vector<double> out;
  for (size_t i = 0; i < p[0].size(); ++i) {
    double m1 =
        ((p[1][i] - p[0][i]) / d0 - (p[2][i] - p[0][i]) / (d0 + d1) + (p[2][i] - p[1][i]) / d1) *
        d1;
    double m2 =
        ((p[2][i] - p[1][i]) / d1 - (p[3][i] - p[1][i]) / (d1 + d2) + (p[3][i] - p[2][i]) / d2) *
        d1;
    out.push_back(h00 * p[1][i] + h10 * m1 + h01 * p[2][i] + h11 * m2);
  }
  return out;
}

TEST(Curve, CatmullRomIsCentripetalForUnevenSpacing) {
  Curve c;
  c.interp = Interp::CatmullRom;
  c.t = {0, 1, 3, 4};
  c.values = {{0, 0, 0}, {0.2, 0, 0}, {5, 3, 1}, {5.5, 9, 1}};
  for (double t : {1.2, 2.0, 2.9}) {
    std::vector<double> got = c.sample(t), want = centripetal_hermite(c.values, (t - 1) / 2);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(got[i], want[i], 1e-9) << t << " component " << i;
  }
}

TEST(Curve, CatmullRomMirrorsEndKeys) {
  // First segment: the virtual key before the first is 2 * p1 - p2.
  Curve c;
  c.interp = Interp::CatmullRom;
  c.t = {0, 1, 2};
  c.values = {{0, 0}, {2, 1}, {3, 3}};
  std::vector<std::vector<double>> first = {{-2, -1}, {0, 0}, {2, 1}, {3, 3}};
  std::vector<std::vector<double>> last = {{0, 0}, {2, 1}, {3, 3}, {4, 5}};
  for (double s : {0.3, 0.6}) {
    EXPECT_NEAR(c.sample(s)[1], centripetal_hermite(first, s)[1], 1e-9);
    EXPECT_NEAR(c.sample(1 + s)[0], centripetal_hermite(last, s)[0], 1e-9);
  }
}

TEST(Curve, CatmullRomWithRepeatedKeysStaysFinite) {
  Curve c;
  c.interp = Interp::CatmullRom;
  c.t = {0, 1, 2, 3, 4};
  c.values = {{1, 1, 1}, {1, 1, 1}, {4, 0, 2}, {4, 0, 2}, {4, 0, 2}};
  for (int i = 0; i <= 400; ++i) {
    std::vector<double> v = c.sample(i * 0.01);
    for (double x : v) ASSERT_TRUE(std::isfinite(x)) << "t = " << i * 0.01;
  }
  EXPECT_EQ(c.sample(0.5), (std::vector<double>{1, 1, 1}));  // a segment between equal keys
  EXPECT_EQ(c.sample(3.5), (std::vector<double>{4, 0, 2}));
  // Between the distinct keys the value stays between them.
  std::vector<double> mid = c.sample(1.5);
  EXPECT_GT(mid[0], 1);
  EXPECT_LT(mid[0], 4);
}

}  // namespace
}  // namespace sdfreel
