// light_beams' shadows: the closed-form visible share against a stratified Monte Carlo over the
// light's span, the penumbra estimator against it, and the seed's one-ray shadow.
#include "scenes/light_beams/visibility.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "scenes/light_beams/crossings.h"

namespace sdfreel::light_beams {
namespace {

constexpr int MC_RAYS = 4096;

// Every shape parked far away (off the picture, out of every light's span), shining (gain 1), so
// every one stands in the others' light (castsShadow).
BeamsUniforms empty_scene() {
  BeamsUniforms u;
  for (int i = 0; i < SHAPE_COUNT; ++i) {
    u.shapes[i] = Shape{SHAPE_CIRCLE, {1000.0f + 10.0f * float(i), 1000.0f}, {}, 0.1f};
    u.color[i] = glm::vec3(1.0f);
    u.gain[i] = 1.0f;
    u.fades[i] = 0.0f;
  }
  return u;
}

// A bounding circle of a shape: disjoint bounds, disjoint shapes.
struct Bound {
  vec2 c;
  float r;
};
Bound bound_of(const Shape& s) {
  if (s.type == SHAPE_CIRCLE) return {s.a, s.r};
  return {0.5f * (s.a + s.b), 0.5f * lengthv(s.b - s.a) + s.r};
}

// SHAPE_COUNT random circles and capsules in [-2, 2]^2 that do not overlap.
BeamsUniforms random_scene(std::mt19937& rng) {
  std::uniform_real_distribution<float> pos(-2.0f, 2.0f), rad(0.03f, 0.3f), len(0.0f, 0.8f),
      ang(0.0f, 6.2831853f);
  BeamsUniforms u = empty_scene();
  for (int i = 0; i < SHAPE_COUNT; ++i) {
    for (int attempt = 0; attempt < 1000; ++attempt) {
      Shape s;
      const vec2 c(pos(rng), pos(rng));
      s.r = rad(rng);
      if (i % 2 == 0) {
        s.type = SHAPE_CIRCLE;
        s.a = s.b = c;
      } else {
        s.type = SHAPE_SEGMENT;
        const float l = len(rng), a = ang(rng);
        s.a = c - l * vec2(std::cos(a), std::sin(a));
        s.b = c + l * vec2(std::cos(a), std::sin(a));
      }
      const Bound b = bound_of(s);
      bool clear = true;
      for (int j = 0; j < i && clear; ++j) {
        const Bound o = bound_of(u.shapes[j]);
        clear = lengthv(b.c - o.c) > b.r + o.r + 0.01f;
      }
      if (clear) {
        u.shapes[i] = s;
        break;
      }
    }
  }
  return u;
}

bool outside_all(vec2 p, const BeamsUniforms& u) {
  for (int j = 0; j < SHAPE_COUNT; ++j)
    if (shapeSDF(p, u.shapes[j]) <= 0.0f) return false;
  return true;
}

TEST(LightBeamsVisibility, ClosedFormAgreesWithStratifiedMonteCarlo) {
  std::mt19937 rng(15);
  std::uniform_real_distribution<float> pos(-2.5f, 2.5f);
  int partial = 0;
  for (int scene = 0; scene < 20; ++scene) {
    BeamsUniforms u = random_scene(rng);
    BeamsUniforms by_rays = u;  // every pair "crossing" without cuts: one order ray per span
    findCrossings(u);           // disjoint: the side of a separating line says which is first
    for (int i = 0; i < SHAPE_COUNT; ++i)
      for (int j = i + 1; j < SHAPE_COUNT; ++j) ASSERT_EQ(u.pair_mode[pairIndex(i, j)], PAIR_APART);
    for (int k = 0; k < 25; ++k) {
      const vec2 p(pos(rng), pos(rng));
      if (!outside_all(p, u)) continue;
      for (int light = 0; light < SHAPE_COUNT; ++light) {
        RayStats stats;
        const float exact = exactVisibility(p, light, u, stats);
        const float mc = monteCarloVisibility(p, light, u, MC_RAYS);
        // Each shadow edge in the span moves the stratified estimate by at most half a stratum;
        // there are at most two per other shape.
        const double tol = 2.0 * (SHAPE_COUNT - 1) * 0.5 / MC_RAYS + 1e-4;
        EXPECT_NEAR(exact, mc, tol) << "scene " << scene << " point " << k << " light " << light;
        EXPECT_NEAR(exactVisibility(p, light, by_rays, stats), mc, tol) << "scene " << scene;
        if (exact > 0.01f && exact < 0.99f) ++partial;
      }
    }
  }
  EXPECT_GT(partial, 50) << "too few penumbra points: the comparison tests little";
}

TEST(LightBeamsVisibility, OneCircleOccluderHasTheClosedFormShareAndThePenumbraIsExact) {
  BeamsUniforms u = empty_scene();
  u.shapes[0] = Shape{SHAPE_CIRCLE, {4.0f, 0.0f}, {}, 1.0f};  // light: half-angle asin(1/4)
  u.shapes[1] = Shape{SHAPE_CIRCLE, {2.0f, 0.6f}, {}, 0.3f};  // occluder above the axis
  findCrossings(u);
  const vec2 p(0.0f, 0.0f);
  const double alpha = std::asin(0.25);
  const double o = std::atan2(0.6, 2.0), g = std::asin(0.3 / std::hypot(2.0, 0.6));
  const double hidden = std::max(0.0, std::min(alpha, o + g) - std::max(-alpha, o - g));
  const double want = 1.0 - hidden / (2.0 * alpha);
  ASSERT_GT(want, 0.1);
  ASSERT_LT(want, 0.9);
  RayStats stats;
  EXPECT_NEAR(exactVisibility(p, 0, u, stats), want, 2e-6);
  EXPECT_NEAR(penumbraVisibility(p, 0, u, stats), want, 2e-6);
  EXPECT_NEAR(monteCarloVisibility(p, 0, u, MC_RAYS), want, 1.0 / MC_RAYS);
}

TEST(LightBeamsVisibility, PenumbraOvercountsOverlappingOccludersTheExactShareDoesNot) {
  BeamsUniforms u = empty_scene();
  u.shapes[0] = Shape{SHAPE_CIRCLE, {4.0f, 0.0f}, {}, 1.0f};
  u.shapes[1] = Shape{SHAPE_CIRCLE, {2.0f, 0.3f}, {}, 0.2f};   // the same angles, one behind the
  u.shapes[2] = Shape{SHAPE_CIRCLE, {1.0f, 0.15f}, {}, 0.1f};  // other: hidden once, not twice
  findCrossings(u);
  RayStats stats;
  const vec2 p(0.0f, 0.0f);
  const float exact = exactVisibility(p, 0, u, stats);
  const float penumbra = penumbraVisibility(p, 0, u, stats);
  EXPECT_NEAR(exact, monteCarloVisibility(p, 0, u, MC_RAYS), 4.0 / MC_RAYS);
  EXPECT_LT(penumbra, exact - 0.05f);
}

TEST(LightBeamsVisibility, ShapesBehindTheLightHideNothing) {
  BeamsUniforms u = empty_scene();
  u.shapes[0] = Shape{SHAPE_CIRCLE, {2.0f, 0.0f}, {}, 0.5f};
  u.shapes[1] = Shape{SHAPE_SEGMENT, {4.0f, -2.0f}, {4.0f, 2.0f}, 0.1f};  // a wall behind it
  findCrossings(u);
  RayStats stats;
  EXPECT_EQ(exactVisibility({0.0f, 0.0f}, 0, u, stats), 1.0f);
  EXPECT_EQ(penumbraVisibility({0.0f, 0.0f}, 0, u, stats), 1.0f);
  EXPECT_EQ(seedShadow({0.0f, 0.0f}, 0, 1.5f, u, stats), 1.0f);
  // From beyond the wall, the wall hides the light entirely.
  EXPECT_EQ(exactVisibility({6.0f, 0.0f}, 0, u, stats), 0.0f);
  EXPECT_EQ(seedShadow({6.0f, 0.0f}, 0, 3.5f, u, stats), 0.0f);
}

// A beam flickered fully out (gain 0) is gone: it hides no light, and inside it the others are
// seen; dimmed (gain above 0) it still stands in their way. The occluder always does.
TEST(LightBeamsVisibility, ABeamThatIsOutCastsNoShadow) {
  BeamsUniforms u = empty_scene();
  u.shapes[0] = Shape{SHAPE_CIRCLE, {2.0f, 0.0f}, {}, 0.5f};
  u.shapes[FIRST_BEAM] = Shape{SHAPE_SEGMENT, {1.0f, -2.0f}, {1.0f, 2.0f}, 0.1f};  // between
  findCrossings(u);
  for (const float beam_gain : {0.0f, 0.3f}) {
    u.gain[FIRST_BEAM] = beam_gain;
    const float want = beam_gain > 0.0f ? 0.0f : 1.0f;
    RayStats stats;
    EXPECT_EQ(exactVisibility({0.0f, 0.0f}, 0, u, stats), want) << beam_gain;
    EXPECT_EQ(penumbraVisibility({0.0f, 0.0f}, 0, u, stats), want) << beam_gain;
    EXPECT_EQ(seedShadow({0.0f, 0.0f}, 0, 1.5f, u, stats), want) << beam_gain;
    EXPECT_EQ(monteCarloVisibility({0.0f, 0.0f}, 0, u, 64), want) << beam_gain;
    EXPECT_EQ(exactVisibility({1.0f, 0.0f}, 0, u, stats), want) << "inside the beam";
  }
  u.shapes[OCCLUDER] = u.shapes[FIRST_BEAM];
  u.gain[FIRST_BEAM] = 0.0f;
  u.gain[OCCLUDER] = 0.0f;  // the occluder is no light, and blocks all the same
  findCrossings(u);
  RayStats stats;
  EXPECT_EQ(exactVisibility({0.0f, 0.0f}, 0, u, stats), 0.0f);
  EXPECT_EQ(seedShadow({0.0f, 0.0f}, 0, 1.5f, u, stats), 0.0f);
}

TEST(LightBeamsVisibility, InsideAnotherShapeNothingIsSeen) {
  BeamsUniforms u = empty_scene();
  u.shapes[0] = Shape{SHAPE_CIRCLE, {2.0f, 0.0f}, {}, 0.5f};
  u.shapes[1] = Shape{SHAPE_CIRCLE, {0.0f, 0.0f}, {}, 0.5f};
  findCrossings(u);
  RayStats stats;
  EXPECT_EQ(exactVisibility({0.1f, 0.0f}, 0, u, stats), 0.0f);
  EXPECT_EQ(penumbraVisibility({0.1f, 0.0f}, 0, u, stats), 0.0f);
  EXPECT_EQ(seedShadow({0.1f, 0.0f}, 0, 1.4f, u, stats), 0.0f);
}

TEST(LightBeamsVisibility, TheSeedsRayIsLitOrNotWhereTheExactShareIsPartial) {
  BeamsUniforms u = empty_scene();
  u.shapes[0] = Shape{SHAPE_CIRCLE, {4.0f, 0.0f}, {}, 1.0f};
  u.shapes[1] = Shape{SHAPE_CIRCLE, {2.0f, 0.45f}, {}, 0.3f};  // grazes the central ray
  findCrossings(u);
  RayStats stats;
  const float exact = exactVisibility({0.0f, 0.0f}, 0, u, stats);
  const float seed = seedShadow({0.0f, 0.0f}, 0, 3.0f, u, stats);
  EXPECT_GT(exact, 0.2f);
  EXPECT_LT(exact, 0.8f);
  EXPECT_TRUE(seed == 0.0f || seed == 1.0f);
  EXPECT_GT(stats.steps, 0u);
}

}  // namespace
}  // namespace sdfreel::light_beams
