// light_beams' shadows where a light and another shape overlap: along one ray either may come
// first, so the order changes inside the angles they share. The closed-form share (cut where the
// outlines cross, crossings.h) against the stratified Monte Carlo, which takes the first hit of
// every ray; and proof that the cuts matter (without them the error is large).
#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <ostream>
#include <random>
#include <string>
#include <vector>

#include "scenes/light_beams/crossings.h"
#include "scenes/light_beams/visibility.h"

namespace sdfreel::light_beams {
namespace {

constexpr int MC_RAYS = 4096;

struct Case {
  std::string name;
  std::vector<Shape> shapes;  // shapes[0] and [1] overlap; every shape is a light in turn
};

const Shape BEAM{SHAPE_SEGMENT, {0.12f, -1.4f}, {0.12f, 1.4f}, 0.02f};

std::vector<Case> cases() {
  return {
      {"two overlapping circles",
       {{SHAPE_CIRCLE, {0.0f, 0.0f}, {}, 0.5f}, {SHAPE_CIRCLE, {0.55f, 0.25f}, {}, 0.35f}}},
      {"circle crossed by a segment", {{SHAPE_CIRCLE, {0.0f, 0.0f}, {}, 0.4f}, BEAM}},
      {"segment crossed by a segment",
       {{SHAPE_SEGMENT, {-0.6f, 0.15f}, {0.6f, -0.1f}, 0.03f}, BEAM}},
      {"segment across a circle's edge",
       {{SHAPE_SEGMENT, {-0.8f, 0.0f}, {0.3f, 0.35f}, 0.05f},
        {SHAPE_CIRCLE, {0.35f, 0.2f}, {}, 0.3f}}},
      {"a circle with a segment end inside it",
       {{SHAPE_CIRCLE, {0.0f, 0.0f}, {}, 0.3f},
        {SHAPE_SEGMENT, {0.2f, 0.1f}, {1.2f, 0.6f}, 0.06f}}},
      {"two overlapping occluders, one across the light",
       {{SHAPE_CIRCLE, {0.0f, 0.0f}, {}, 0.3f},
        {SHAPE_CIRCLE, {0.4f, 0.1f}, {}, 0.25f},
        {SHAPE_SEGMENT, {0.3f, -0.9f}, {0.75f, 0.8f}, 0.04f}}},
  };
}

void PrintTo(const Case& c, std::ostream* os) {
  *os << c.name;
}

BeamsUniforms scene_of(const Case& c) {
  BeamsUniforms u;
  for (int i = 0; i < SHAPE_COUNT; ++i) {  // the unused shapes far away, out of every span
    u.shapes[i] = Shape{SHAPE_CIRCLE, {1000.0f + 10.0f * float(i), 1000.0f}, {}, 0.1f};
    u.gain[i] = 1.0f;  // all shining: every shape stands in the others' light (castsShadow)
  }
  for (size_t i = 0; i < c.shapes.size(); ++i) u.shapes[i] = c.shapes[i];
  findCrossings(u);
  return u;
}

bool outside_all(vec2 p, const BeamsUniforms& u) {
  for (const Shape& s : u.shapes)
    if (shapeSDF(p, s) <= 0.0f) return false;
  return true;
}

class LightBeamsOverlap : public ::testing::TestWithParam<Case> {};

TEST_P(LightBeamsOverlap, ClosedFormAgreesWithStratifiedMonteCarlo) {
  const Case& c = GetParam();
  const BeamsUniforms u = scene_of(c);
  ASSERT_GT(u.crossing_first[pairIndex(0, 1) + 1] - u.crossing_first[pairIndex(0, 1)], 0)
      << "the outlines of shapes 0 and 1 must cross";
  BeamsUniforms uncut = u;  // the same scene without the cuts: one ray per shared span
  for (int& k : uncut.crossing_first) k = 0;
  std::mt19937 rng(14);
  std::uniform_real_distribution<float> pos(-1.6f, 1.6f);
  int compared = 0, partial = 0, wrong_uncut = 0;
  for (int k = 0; k < 300; ++k) {
    const vec2 p(pos(rng), pos(rng));
    if (!outside_all(p, u)) continue;
    for (int light = 0; light < int(c.shapes.size()); ++light) {
      RayStats stats;
      const float exact = exactVisibility(p, light, u, stats);
      const float mc = monteCarloVisibility(p, light, u, MC_RAYS);
      // Half a stratum per shadow edge: two per part, at most 1 + MAX_PAIR_CROSSINGS parts per
      // other shape.
      const double tol = 2.0 * (1 + MAX_PAIR_CROSSINGS) * (c.shapes.size() - 1) * 0.5 / MC_RAYS;
      EXPECT_NEAR(exact, mc, tol) << c.name << ", point " << p.x << " " << p.y << ", light "
                                  << light;
      ++compared;
      if (mc > 0.01f && mc < 0.99f) ++partial;
      if (std::abs(exactVisibility(p, light, uncut, stats) - mc) > 0.05f) ++wrong_uncut;
      // One other shape: the penumbra product is that shape's share alone, exact as well.
      if (c.shapes.size() == 2) {
        EXPECT_NEAR(penumbraVisibility(p, light, u, stats), exact, 1e-6) << c.name;
      }
    }
  }
  EXPECT_GT(compared, 200) << c.name;
  EXPECT_GT(partial, 20) << c.name << ": too few points in a penumbra";
  EXPECT_GT(wrong_uncut, 5) << c.name << ": the case does not need the cuts";
}

INSTANTIATE_TEST_SUITE_P(Cases, LightBeamsOverlap, ::testing::ValuesIn(cases()),
                         [](const ::testing::TestParamInfo<Case>& info) {
                           std::string name;
                           for (const char ch : info.param.name)
                             if (std::isalnum(static_cast<unsigned char>(ch))) name += ch;
                           return name;
                         });

TEST(LightBeamsCrossings, OutlinesCrossWhereBothDistancesAreZero) {
  BeamsUniforms u;
  for (int i = 0; i < SHAPE_COUNT; ++i)
    u.shapes[i] = Shape{SHAPE_CIRCLE, {100.0f * float(i), 0.0f}, {}, 1.0f};
  u.shapes[0] = Shape{SHAPE_CIRCLE, {0.0f, 0.0f}, {}, 1.0f};
  u.shapes[1] = Shape{SHAPE_CIRCLE, {1.0f, 0.0f}, {}, 1.0f};               // two points
  u.shapes[2] = Shape{SHAPE_SEGMENT, {-3.0f, 0.5f}, {3.0f, 0.5f}, 0.25f};  // four with 0, 1 each
  u.shapes[3] = Shape{SHAPE_CIRCLE, {0.0f, 0.0f}, {}, 0.5f};               // inside 0: none
  u.shapes[4] = Shape{SHAPE_SEGMENT, {5.0f, 0.0f}, {5.0f, 0.0f}, 0.5f};    // ends equal: none
  findCrossings(u);
  const auto count = [&](int i, int j) {
    return u.crossing_first[pairIndex(i, j) + 1] - u.crossing_first[pairIndex(i, j)];
  };
  EXPECT_EQ(count(0, 1), 2);
  EXPECT_EQ(count(0, 2), 4);
  EXPECT_EQ(count(1, 2), 4);
  EXPECT_EQ(count(0, 3), 0);
  EXPECT_EQ(count(0, 4), 0);
  EXPECT_EQ(count(2, 3), 2);  // the stroke's lower side y = 0.25 cuts the small circle twice
  for (int i = 0; i < SHAPE_COUNT; ++i)
    for (int j = i + 1; j < SHAPE_COUNT; ++j)
      for (int k = u.crossing_first[pairIndex(i, j)]; k < u.crossing_first[pairIndex(i, j) + 1];
           ++k) {
        EXPECT_NEAR(shapeSDF(u.crossings[k], u.shapes[i]), 0.0f, 1e-6f) << i << " " << j;
        EXPECT_NEAR(shapeSDF(u.crossings[k], u.shapes[j]), 0.0f, 1e-6f) << i << " " << j;
      }
}

}  // namespace
}  // namespace sdfreel::light_beams
