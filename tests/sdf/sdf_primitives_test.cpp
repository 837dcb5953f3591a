// Exact values of the primitives at points where the distance is known by hand, the operators'
// edge cases (k = 0, zero vectors), and the 1-Lipschitz property that sphere tracing relies on.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>

#include "sdf/sdf.h"

namespace sdfreel {
namespace {

using glm::vec2;
using glm::vec3;

TEST(SdfPrimitives, BoxInsideOutsideAndCorner) {
  const vec3 b(1.0f, 2.0f, 3.0f);
  EXPECT_FLOAT_EQ(sdBox(vec3(0.0f), b), -1.0f);  // nearest face is x
  EXPECT_FLOAT_EQ(sdBox(vec3(3.0f, 0.0f, 0.0f), b), 2.0f);
  EXPECT_FLOAT_EQ(sdBox(vec3(0.0f, -2.5f, 0.0f), b), 0.5f);
  EXPECT_FLOAT_EQ(sdBox(vec3(2.0f, 3.0f, 3.0f), b), std::sqrt(2.0f));  // off an edge
  EXPECT_FLOAT_EQ(sdBox(vec3(4.0f, 6.0f, 3.0f), b), 5.0f);             // 3-4-5 off an edge
}

TEST(SdfPrimitives, RoundBoxIsBoxWithRoundedCorners) {
  const vec3 b(1.0f);
  EXPECT_FLOAT_EQ(sdRoundBox(vec3(2.0f, 0.0f, 0.0f), b, 0.25f), 1.0f);  // faces stay put
  // Corner: the sphere of radius 0.25 centred at (0.75, 0.75, 0.75).
  const vec3 p(2.0f);
  EXPECT_FLOAT_EQ(sdRoundBox(p, b, 0.25f), glm::length(p - vec3(0.75f)) - 0.25f);
  EXPECT_FLOAT_EQ(sdRoundBox(vec3(0.0f), b, 0.0f), sdBox(vec3(0.0f), b));
}

TEST(SdfPrimitives, SphereTorusCylinder) {
  EXPECT_FLOAT_EQ(sdSphere(vec3(0.0f, 3.0f, 4.0f), 2.0f), 3.0f);
  EXPECT_FLOAT_EQ(sdTorus(vec3(2.0f, 0.0f, 0.0f), vec2(2.0f, 0.5f)), -0.5f);  // tube centre
  EXPECT_FLOAT_EQ(sdTorus(vec3(0.0f), vec2(2.0f, 0.5f)), 1.5f);               // hole centre
  EXPECT_FLOAT_EQ(sdTorus(vec3(0.0f, 0.0f, 3.5f), vec2(2.0f, 0.5f)), 1.0f);
  EXPECT_FLOAT_EQ(sdCappedCylinder(vec3(0.0f), 2.0f, 1.0f), -1.0f);  // h = half height
  EXPECT_FLOAT_EQ(sdCappedCylinder(vec3(3.0f, 0.0f, 0.0f), 2.0f, 1.0f), 2.0f);
  EXPECT_FLOAT_EQ(sdCappedCylinder(vec3(0.0f, -5.0f, 0.0f), 2.0f, 1.0f), 3.0f);
  EXPECT_FLOAT_EQ(sdCappedCylinder(vec3(4.0f, 6.0f, 0.0f), 2.0f, 1.0f), 5.0f);  // off the rim
  // Offset variant: the same cylinder moved to (0.5, y, -0.25).
  const vec3 p(1.7f, 0.3f, -1.1f);
  EXPECT_FLOAT_EQ(sdCappedCylinderOffset(p, 1.0f, 0.2f, vec2(0.5f, -0.25f)),
                  sdCappedCylinder(p - vec3(0.5f, 0.0f, -0.25f), 1.0f, 0.2f));
}

TEST(SdfPrimitives, CappedTorusHalfRing) {
  const vec2 half(1.0f, 0.0f);  // sin, cos of 90 degrees: the upper half of the ring
  const float ra = 1.0f, rb = 0.1f;
  EXPECT_FLOAT_EQ(sdCappedTorus(vec3(0.0f, 1.0f, 0.0f), half, ra, rb), -rb);   // on the arc
  EXPECT_FLOAT_EQ(sdCappedTorus(vec3(-1.0f, 0.0f, 0.0f), half, ra, rb), -rb);  // an end
  // Below the cut the nearest arc point is an end, (+-1, 0).
  EXPECT_FLOAT_EQ(sdCappedTorus(vec3(0.0f, -1.0f, 0.0f), half, ra, rb), std::sqrt(2.0f) - rb);
  // Exactly on the ring the radicand can round below 0: the result must stay finite.
  for (int i = 0; i < 1000; ++i) {
    const float a = 0.0031f * i;
    EXPECT_TRUE(std::isfinite(
        sdCappedTorus(vec3(0.7f * dm::sin(a), 0.7f * dm::cos(a), 0.0f), half, 0.7f, 0.05f)));
  }
}

TEST(SdfPrimitives, PlaneSegmentCircle) {
  EXPECT_FLOAT_EQ(sdPlane(vec3(1.0f, 3.0f, 2.0f), vec3(0.0f, 1.0f, 0.0f), 1.0f), 4.0f);
  EXPECT_FLOAT_EQ(sdSegment(vec3(1.0f, 2.0f, 0.0f), vec3(0.0f), vec3(2.0f, 0.0f, 0.0f)), 2.0f);
  EXPECT_FLOAT_EQ(sdSegment(vec3(5.0f, 0.0f, 0.0f), vec3(0.0f), vec3(2.0f, 0.0f, 0.0f)), 3.0f);
  EXPECT_FLOAT_EQ(sdSegment(vec3(3.0f, 4.0f, 0.0f), vec3(0.0f), vec3(0.0f)), 5.0f);  // a == b
  EXPECT_FLOAT_EQ(sdSegment(vec2(3.0f, 4.0f), vec2(0.0f), vec2(0.0f)), 5.0f);
  EXPECT_FLOAT_EQ(sdSegment(vec2(1.0f, -1.0f), vec2(0.0f), vec2(2.0f, 0.0f)), 1.0f);
  EXPECT_FLOAT_EQ(sdCapsule(vec3(1.0f, 2.0f, 0.0f), vec3(0.0f), vec3(2.0f, 0.0f, 0.0f), 0.5f),
                  1.5f);
  EXPECT_FLOAT_EQ(sdCircle(vec2(3.0f, 4.0f), 1.0f), 4.0f);
  EXPECT_FLOAT_EQ(sdRoundRect(vec2(3.0f, 0.0f), vec2(1.0f, 1.0f), 0.5f), 2.0f);
  EXPECT_FLOAT_EQ(sdRoundRect(vec2(2.0f, 2.0f), vec2(1.0f, 1.0f), 0.5f),
                  glm::length(vec2(1.5f)) - 0.5f);
}

TEST(SdfOperators, SmoothOperatorsWithZeroKAreHard) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(-3.0f, 3.0f);
  for (int i = 0; i < 10000; ++i) {
    const float a = u(rng), b = u(rng);
    ASSERT_EQ(opSmoothUnion(a, b, 0.0f), std::min(a, b));
    ASSERT_EQ(opSmoothSubtraction(a, b, 0.0f), std::max(-a, b));
    ASSERT_EQ(opSmoothIntersection(a, b, 0.0f), std::max(a, b));
    ASSERT_EQ(opSmoothUnion(a, b, -1.0f), std::min(a, b));  // negative k: hard as well
  }
}

TEST(SdfOperators, SmoothUnionStaysWithinQuarterKOfMin) {
  std::mt19937 rng(8);
  std::uniform_real_distribution<float> u(-3.0f, 3.0f);
  const float k = 0.4f;
  for (int i = 0; i < 10000; ++i) {
    const float a = u(rng), b = u(rng);
    const float s = opSmoothUnion(a, b, k);
    ASSERT_LE(s, std::min(a, b) + 1e-6f);
    ASSERT_GE(s, std::min(a, b) - 0.25f * k - 1e-6f);
    if (std::abs(a - b) >= k) {
      ASSERT_FLOAT_EQ(s, std::min(a, b));  // no blending far apart
    }
  }
  // Equal inputs get the full blend: min - k/4.
  EXPECT_FLOAT_EQ(opSmoothUnion(1.0f, 1.0f, k), 1.0f - 0.25f * k);
}

TEST(SdfOperators, HardOperatorsOnionRoundSymmetry) {
  EXPECT_EQ(opUnion(1.0f, -2.0f), -2.0f);
  EXPECT_EQ(opSubtraction(1.0f, -2.0f), -1.0f);  // d2 minus d1
  EXPECT_EQ(opIntersection(1.0f, -2.0f), 1.0f);
  EXPECT_EQ(opOnion(-0.5f, 0.1f), 0.4f);
  EXPECT_EQ(opOnion(0.05f, 0.1f), -0.05f);
  EXPECT_EQ(opRound(1.0f, 0.25f), 0.75f);
  EXPECT_EQ(opSymXZ(vec3(-1.0f, -2.0f, -3.0f)), vec3(1.0f, -2.0f, 3.0f));
}

TEST(SdfHelpers, SafeNormalize) {
  EXPECT_EQ(safe_normalize(vec3(0.0f)), vec3(0.0f, 1.0f, 0.0f));
  EXPECT_EQ(safe_normalize(vec3(1e-30f, 0.0f, 0.0f)), vec3(0.0f, 1.0f, 0.0f));
  const vec3 n = safe_normalize(vec3(3.0f, 0.0f, -4.0f));
  EXPECT_FLOAT_EQ(n.x, 0.6f);
  EXPECT_FLOAT_EQ(n.z, -0.8f);
  const vec3 tiny = safe_normalize(vec3(1e-10f, 2e-10f, 0.0f));  // small but usable
  EXPECT_NEAR(glm::length(tiny), 1.0f, 1e-6f);
  EXPECT_GT(tiny.y, tiny.x);
}

TEST(SdfHelpers, RotateYKeepsLengthAndTurnsXTowardMinusZ) {
  const float a = 0.3f;
  const vec3 r = rotateY(vec3(1.0f, 2.0f, 0.0f), dm::cos(a), dm::sin(a));
  EXPECT_NEAR(glm::length(r), std::sqrt(5.0f), 1e-6f);
  EXPECT_FLOAT_EQ(r.y, 2.0f);
  EXPECT_LT(r.z, 0.0f);
}

// |f(p) - f(q)| <= |p - q| on random pairs: the sphere-tracing step is safe.
void expect_lipschitz(const std::function<float(const vec3&)>& f, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(-2.5f, 2.5f), small(-0.05f, 0.05f);
  for (int i = 0; i < 20000; ++i) {
    const vec3 p(u(rng), u(rng), u(rng));
    const vec3 q = p + vec3(small(rng), small(rng), small(rng));
    const float fp = f(p), fq = f(q);
    ASSERT_TRUE(std::isfinite(fp));
    ASSERT_LE(std::abs(fp - fq), glm::length(p - q) * 1.0001f + 1e-6f) << i;
  }
}

TEST(SdfPrimitives, AllAreOneLipschitz) {
  expect_lipschitz([](const vec3& p) { return sdBox(p, vec3(1.0f, 0.5f, 0.7f)); }, 1);
  expect_lipschitz([](const vec3& p) { return sdRoundBox(p, vec3(1.0f, 0.5f, 0.7f), 0.2f); }, 2);
  expect_lipschitz([](const vec3& p) { return sdTorus(p, vec2(1.0f, 0.3f)); }, 3);
  expect_lipschitz([](const vec3& p) { return sdCappedTorus(p, vec2(0.8f, 0.6f), 1.0f, 0.1f); }, 4);
  expect_lipschitz([](const vec3& p) { return sdCappedCylinder(p, 1.0f, 0.5f); }, 5);
  expect_lipschitz(
      [](const vec3& p) {
        return opSmoothUnion(sdSphere(p, 1.0f), sdBox(p - vec3(1.0f), vec3(0.5f)), 0.3f);
      },
      6);
  expect_lipschitz(
      [](const vec3& p) {
        return opSmoothSubtraction(sdSphere(p, 1.0f), sdBox(p, vec3(1.2f)), 0.2f);
      },
      7);
  expect_lipschitz(
      [](const vec3& p) { return sdCappedCylinderOffset(opSymXZ(p), 1.0f, 0.05f, vec2(0.53f)); },
      8);
}

}  // namespace
}  // namespace sdfreel
