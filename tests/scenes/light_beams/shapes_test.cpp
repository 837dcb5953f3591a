// light_beams' 2D shapes against analytic distances, spans and ray hits.
#include "scenes/light_beams/shapes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace sdfreel::light_beams {
namespace {

TEST(LightBeamsShapes, CircleDistanceIsDistanceToCentreMinusRadius) {
  EXPECT_FLOAT_EQ(circleSDF({3.0f, 4.0f}, {0.0f, 0.0f}, 1.0f), 4.0f);
  EXPECT_FLOAT_EQ(circleSDF({0.0f, 0.0f}, {0.0f, 0.0f}, 0.5f), -0.5f);
  EXPECT_EQ(circleSDF({0.5f, 0.0f}, {0.0f, 0.0f}, 0.5f), 0.0f);  // on the outline: exactly 0
}

TEST(LightBeamsShapes, SegmentDistanceMatchesAnalyticDistances) {
  const vec2 a(-1.0f, 0.0f), b(1.0f, 0.0f);
  EXPECT_FLOAT_EQ(segmentSDF({0.3f, 2.0f}, a, b, 0.25f), 1.75f);   // beside: perpendicular
  EXPECT_FLOAT_EQ(segmentSDF({4.0f, 4.0f}, a, b, 0.0f), 5.0f);     // beyond b: distance to b
  EXPECT_FLOAT_EQ(segmentSDF({-1.0f, -3.0f}, a, b, 1.0f), 2.0f);   // above an end
  EXPECT_FLOAT_EQ(segmentSDF({0.0f, 0.1f}, a, b, 0.25f), -0.15f);  // inside the stroke
  // Random points against the distance to the closest of many points along the segment.
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> c(-3.0f, 3.0f);
  for (int k = 0; k < 200; ++k) {
    const vec2 p(c(rng), c(rng)), s0(c(rng), c(rng)), s1(c(rng), c(rng));
    double best = 1e30;
    for (int i = 0; i <= 20000; ++i) {
      const double h = i / 20000.0;
      const double x = s0.x + (s1.x - s0.x) * h, y = s0.y + (s1.y - s0.y) * h;
      best = std::min(best, std::hypot(p.x - x, p.y - y));
    }
    EXPECT_NEAR(segmentSDF(p, s0, s1, 0.1f), best - 0.1, 2e-4) << k;
  }
}

TEST(LightBeamsShapes, SegmentWithBothEndsEqualIsACircle) {
  const vec2 a(0.5f, -0.25f);
  for (const vec2 p : {vec2(2.0f, 1.0f), vec2(0.5f, -0.25f), vec2(-3.0f, 0.0f)}) {
    EXPECT_EQ(segmentSDF(p, a, a, 0.2f), circleSDF(p, a, 0.2f));
    EXPECT_TRUE(std::isfinite(segmentSDF(p, a, a, 0.2f)));
  }
  const Shape dot{SHAPE_SEGMENT, a, a, 0.2f};
  const vec2 span = angularSpan({2.5f, -0.25f}, {-1.0f, 0.0f}, dot);
  EXPECT_NEAR(span.x, -std::asin(0.1), 1e-6);
  EXPECT_NEAR(span.y, std::asin(0.1), 1e-6);
  EXPECT_NEAR(hitShape({2.5f, -0.25f}, {-1.0f, 0.0f}, dot), 1.8f, 1e-6);
}

TEST(LightBeamsShapes, ClosestPointLiesOnTheOutlineTowardThePoint) {
  const Shape seg{SHAPE_SEGMENT, {-1.0f, 0.0f}, {1.0f, 0.0f}, 0.25f};
  const vec2 q = closestPoint({0.3f, 2.0f}, seg);
  EXPECT_FLOAT_EQ(q.x, 0.3f);
  EXPECT_FLOAT_EQ(q.y, 0.25f);
  const Shape circle{SHAPE_CIRCLE, {1.0f, 1.0f}, {}, 1.0f};
  const vec2 c = closestPoint({4.0f, 5.0f}, circle);
  EXPECT_FLOAT_EQ(c.x, 1.6f);
  EXPECT_FLOAT_EQ(c.y, 1.8f);
}

TEST(LightBeamsShapes, CapsuleSpanIsTheHullOfItsEndDiscs) {
  // A vertical capsule x = 2, y in [-1, 1], stroke 0.5, seen from the origin along +x.
  const Shape cap{SHAPE_SEGMENT, {2.0f, -1.0f}, {2.0f, 1.0f}, 0.5f};
  const vec2 span = angularSpan({0.0f, 0.0f}, {1.0f, 0.0f}, cap);
  const double end = std::atan2(1.0, 2.0) + std::asin(0.5 / std::sqrt(5.0));
  EXPECT_NEAR(span.x, -end, 1e-6);
  EXPECT_NEAR(span.y, end, 1e-6);
  // Seen from behind its own reference direction: a shape behind the viewer stays behind.
  const vec2 back = angularSpan({0.0f, 0.0f}, {-1.0f, 0.0f}, cap);
  EXPECT_GT(std::min(std::abs(back.x), std::abs(back.y)), 1.5707963);
}

TEST(LightBeamsShapes, RayHitsMatchAnalyticDistances) {
  const Shape circle{SHAPE_CIRCLE, {3.0f, 0.0f}, {}, 1.0f};
  EXPECT_FLOAT_EQ(hitShape({0.0f, 0.0f}, {1.0f, 0.0f}, circle), 2.0f);
  EXPECT_EQ(hitShape({0.0f, 0.0f}, {-1.0f, 0.0f}, circle), NO_HIT);
  EXPECT_EQ(hitShape({0.0f, 0.0f}, {0.0f, 1.0f}, circle), NO_HIT);
  const Shape cap{SHAPE_SEGMENT, {2.0f, -1.0f}, {2.0f, 1.0f}, 0.5f};
  EXPECT_FLOAT_EQ(hitShape({0.0f, 0.5f}, {1.0f, 0.0f}, cap), 1.5f);     // the long side
  EXPECT_NEAR(hitShape({2.0f, 3.0f}, {0.0f, -1.0f}, cap), 1.5f, 1e-6);  // the end disc
  EXPECT_EQ(hitShape({0.0f, 3.0f}, {1.0f, 0.0f}, cap), NO_HIT);
}

}  // namespace
}  // namespace sdfreel::light_beams
