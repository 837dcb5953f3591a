// The distance bounds of water_lily's reshaped parts: with each part divided by its Lipschitz
// bound (geometry.h), no pair of nearby points may differ in distance by more than their
// separation, at the largest curl the scene hands out. Without the division the reshaped petal is
// steeper than a distance: the bound is needed, and the blanket 0.1 of the naive preset is far
// more than needed.
#include <gtest/gtest.h>

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

TEST(WaterLilyLipschitz, EveryPetalLayerDividedByItsBoundIsOneLipschitz) {
  const LilyUniforms u = uniforms_at_curl(MAX_CURL, false);
  for (int l = 0; l < PETAL_LAYERS; ++l) {
    const float s =
        steepest([&](const glm::vec3& q) { return petalLayer(q, l, 0.3f, MAX_CURL, u).x; },
                 FLOWER_BOX_CENTER, FLOWER_BOX, 11u + uint32_t(l));
    EXPECT_LE(s, 1.0f + ROUNDING) << "layer " << l << " bound " << u.petal_lipschitz[l];
    // ... and the bound is tight within a factor of two.
    EXPECT_GT(s, 0.5f) << "layer " << l;
    std::printf("layer %d: bound %.3f, steepest after dividing %.3f\n", l, u.petal_lipschitz[l], s);
  }
}

TEST(WaterLilyLipschitz, RawReshapedPetalIsSteeperThanADistance) {
  LilyUniforms u = uniforms_at_curl(MAX_CURL, false);
  for (int l = 0; l < PETAL_LAYERS; ++l) u.petal_lipschitz[l] = 1.0f;
  const float s =
      steepest([&](const glm::vec3& q) { return petalLayer(q, 2, 0.0f, MAX_CURL, u).x; },
               FLOWER_BOX_CENTER, FLOWER_BOX, 5u);
  EXPECT_GT(s, 1.2f);
}

TEST(WaterLilyLipschitz, WholeFlowerAndPadsAreOneLipschitzAtEveryCurl) {
  for (float curl : {0.0f, 0.8f, MAX_CURL}) {
    const LilyUniforms u = uniforms_at_curl(curl, false);
    const FlowerPlacement& f = FLOWERS[1];
    const glm::vec3 c(f.xz.x, 0.3f * f.scale, f.xz.y);
    EXPECT_LE(steepest([&](const glm::vec3& p) { return lilyFlower(p, 1, u); }, c,
                       FLOWER_BOX * f.scale, 21u),
              1.0f + ROUNDING)
        << curl;
  }
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
TEST(WaterLilyLipschitz, PartsLieInsideTheirBounds) {
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

}  // namespace
}  // namespace sdfreel::water_lily
