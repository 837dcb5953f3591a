// The distance bounds of water_lily's reshaped parts. A petal layer steps with the ellipsoid
// bound divided by the Lipschitz bound of its reshaping (geometry.h): the sphere of that radius
// around any point must hold no part of the flower ("unbounding spheres are empty"). The seed's
// flattened sphere is far steeper (its real Lipschitz bound is the flattening times the
// reshaping, above 20), so the blanket 0.1 of the naive preset is not even a bound. The pads are
// plain distances divided by the bound of their rim lift: 1-Lipschitz.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "scenes/water_lily/geometry.h"

namespace sdfreel::water_lily {
namespace {

constexpr int PAIRS = 200000;
constexpr float SEPARATION = 2e-3f;  // small: the ratio approaches the gradient's length
constexpr float ROUNDING = 2e-3f;    // relative slack for float rounding of the differences

LilyUniforms uniforms_at_curl(float curl, bool naive) {
  LilyUniforms u;
  for (int f = 0; f < FLOWER_COUNT; ++f) u.curl[f] = curl;
  for (int l = 0; l < PETAL_LAYERS; ++l)
    u.petal_lipschitz[l] = petalLipschitz(LAYERS[l], curl * LAYERS[l].curl);
  for (int i = 0; i < LEAF_COUNT; ++i) u.leaf_lipschitz[i] = leafLipschitz(LEAVES[i]);
  u.naive = naive;
  return u;
}

// The largest |d(a) - d(b)| / |a - b| over random pairs in a box of half size `half` at `c`.
template <class F>
float steepest(F d, const glm::vec3& c, const glm::vec3& half, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
  float worst = 0.0f;
  for (int i = 0; i < PAIRS; ++i) {
    const glm::vec3 a = c + half * glm::vec3(unit(rng), unit(rng), unit(rng));
    const glm::vec3 dir = glm::normalize(glm::vec3(unit(rng), unit(rng), unit(rng)));
    const glm::vec3 b = a + dir * SEPARATION;
    worst = std::max(worst, std::abs(d(a) - d(b)) / glm::length(b - a));
  }
  return worst;
}

const glm::vec3 FLOWER_BOX(0.8f, 0.6f, 0.8f);
const glm::vec3 FLOWER_BOX_CENTER(0.0f, 0.3f, 0.0f);

// Random points around a flower; for each outside one, random points inside its unbounding
// sphere (radius = the bound there): none may be inside the flower. Returns how many points were
// tested.
template <class F>
int checkEmptySpheres(F d, const glm::vec3& c, const glm::vec3& half, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f), share(0.0f, 1.0f);
  int tested = 0;
  for (int i = 0; i < PAIRS / 20; ++i) {
    const glm::vec3 p = c + half * glm::vec3(unit(rng), unit(rng), unit(rng));
    const float r = d(p);
    if (!(r > 0.0f)) continue;
    ++tested;
    for (int k = 0; k < 24; ++k) {
      const glm::vec3 dir = glm::normalize(glm::vec3(unit(rng), unit(rng), unit(rng)));
      const float f = std::cbrt(share(rng)) * (1.0f - ROUNDING);  // uniform in the ball
      const glm::vec3 q = p + dir * (r * f);
      if (d(q) < 0.0f) {
        ADD_FAILURE() << "bound " << r << " at (" << p.x << ", " << p.y << ", " << p.z
                      << ") but inside at distance " << r * f;
        return tested;
      }
    }
  }
  return tested;
}

TEST(WaterLilyBounds, UnboundingSpheresOfEveryLayerAndFlowerAreEmpty) {
  for (float curl : {0.0f, 1.0f, MAX_CURL}) {
    const LilyUniforms u = uniforms_at_curl(curl, false);
    for (int l = 0; l < PETAL_LAYERS; ++l)
      EXPECT_GT(
          checkEmptySpheres([&](const glm::vec3& q) { return petalLayer(q, l, 0.3f, curl, u).x; },
                            FLOWER_BOX_CENTER, FLOWER_BOX, 11u + uint32_t(l)),
          1000)
          << "layer " << l << " curl " << curl;
    const FlowerPlacement& f = FLOWERS[1];
    const glm::vec3 c(f.xz.x, 0.3f * f.scale, f.xz.y);
    EXPECT_GT(checkEmptySpheres([&](const glm::vec3& p) { return lilyFlower(p, 1, u); }, c,
                                FLOWER_BOX * f.scale, 21u),
              1000)
        << "curl " << curl;
  }
}

// The bound is useful: next to the petals it is within a small factor of the seed's
// (Lipschitz-corrected) value, far larger than what the seed's construction allows.
TEST(WaterLilyBounds, SeedsFlattenedSphereIsSteeperThanItsBlanketFactorAllows) {
  const LilyUniforms naive = uniforms_at_curl(MAX_CURL, true);
  for (int l = 0; l < PETAL_LAYERS; ++l) {
    // naive: the seed's sphere times 0.1. Steeper than 1: the blanket factor is not a bound.
    const float s =
        steepest([&](const glm::vec3& q) { return petalLayer(q, l, 0.0f, MAX_CURL, naive).x; },
                 FLOWER_BOX_CENTER, FLOWER_BOX, 5u + uint32_t(l));
    EXPECT_GT(s, 1.2f) << "layer " << l;
    // Its real Lipschitz bound: flattening times reshaping.
    const float real = flattenLipschitz(LAYERS[l]) *
                       petalLipschitz(LAYERS[l], MAX_CURL * LAYERS[l].curl) * NAIVE_PETAL_FACTOR;
    EXPECT_LE(s, real * (1.0f + ROUNDING)) << "layer " << l;
    std::printf("layer %d: seed's sphere x 0.1 is %.2f-Lipschitz (bound %.2f)\n", l, s, real);
  }
}

TEST(WaterLilyBounds, PadsAreOneLipschitz) {
  const LilyUniforms u = uniforms_at_curl(1.0f, false);
  for (int i : {0, 3, 12}) {
    const glm::vec3 c(LEAVES[i].xz.x, 0.03f, LEAVES[i].xz.y);
    const float r = LEAVES[i].radius * 1.3f;
    EXPECT_LE(steepest([&](const glm::vec3& p) { return lilyPad(p, i, u); }, c,
                       glm::vec3(r, 0.1f, r), 31u + uint32_t(i)),
              1.0f + ROUNDING)
        << "leaf " << i;
  }
}

// A bound stands in for a part only if the part lies inside it: no point outside a bound may be
// inside its part (at the largest curl, where the petals reach highest).
TEST(WaterLilyBounds, PartsLieInsideTheirBounds) {
  const LilyUniforms u = uniforms_at_curl(MAX_CURL, false);
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
  int inside = 0;
  for (int i = 0; i < PAIRS; ++i) {
    const glm::vec3 p(4.0f * unit(rng), 0.3f + 0.35f * unit(rng), 4.5f + 4.5f * unit(rng));
    for (int f = 0; f < FLOWER_COUNT; ++f) {
      const float d = lilyFlower(p, f, u);
      inside += d < 0.0f;
      if (d < 0.0f) {
        ASSERT_LT(flowerBound(p, f), 0.0f) << f;
      }
    }
    for (int l = 0; l < LEAF_COUNT; ++l) {
      if (lilyPad(p, l, u) < 0.0f) {
        ASSERT_LT(leafBound(p, l, u), 0.0f) << l;
      }
    }
    ASSERT_GT(SLAB_TOP, p.y * float(lilyFlower(p, 0, u) < 0.0f));
  }
  EXPECT_GT(inside, 100);  // the samples do reach into the flowers
}

// Every pad (the drifting one at its largest drift) and flower lies in the field box.
TEST(WaterLilyBounds, FieldBoxHoldsEveryPart) {
  for (int f = 0; f < FLOWER_COUNT; ++f) {
    const FlowerPlacement& fl = FLOWERS[f];
    const float r = FLOWER_BOUND_RADIUS * fl.scale;
    EXPECT_GT(fl.xz.x - r, FIELD_MIN.x) << f;
    EXPECT_LT(fl.xz.x + r, FIELD_MAX.x) << f;
    EXPECT_GT(fl.xz.y - r, FIELD_MIN.z) << f;
    EXPECT_LT(fl.xz.y + r, FIELD_MAX.z) << f;
  }
  const float max_drift = 1.0f;  // the leaf_drift parameter's maximum
  for (int i = 0; i < LEAF_COUNT; ++i) {
    const float r = LEAVES[i].radius + (i == DRIFTING_LEAF ? max_drift : 0.0f);
    EXPECT_GT(LEAVES[i].xz.x - r, FIELD_MIN.x) << i;
    EXPECT_LT(LEAVES[i].xz.x + r, FIELD_MAX.x) << i;
    EXPECT_GT(LEAVES[i].xz.y - r, FIELD_MIN.z) << i;
    EXPECT_LT(LEAVES[i].xz.y + r, FIELD_MAX.z) << i;
  }
}

}  // namespace
}  // namespace sdfreel::water_lily
