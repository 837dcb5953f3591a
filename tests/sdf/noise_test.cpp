// Hashes must be stable forever (golden frames depend on them) and identical to the GPU version;
// noise must be deterministic, in range, continuous and seed-dependent.
#include "sdf/noise.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <set>

namespace sdfreel {
namespace {

using glm::vec2;
using glm::vec3;

// The PCG hash re-derived with 64-bit arithmetic and explicit masking, independent of the
// uint32 wrap-around the real one relies on.
uint32_t reference_pcg(uint32_t v) {
  const uint64_t mask = 0xffffffffull;
  const uint64_t state = (uint64_t(v) * 747796405ull + 2891336453ull) & mask;
  const uint64_t shift = (state >> 28) + 4;
  const uint64_t word = (((state >> shift) ^ state) * 277803737ull) & mask;
  return uint32_t(((word >> 22) ^ word) & mask);
}

TEST(Noise, PcgHashMatchesReferenceAndGoldenValues) {
  for (uint32_t v = 0; v < 200000; ++v)
    ASSERT_EQ(pcg_hash(v * 2654435761u), reference_pcg(v * 2654435761u));
  // Values from an independent Python implementation of the published algorithm.
  EXPECT_EQ(pcg_hash(0u), 129708002u);
  EXPECT_EQ(pcg_hash(1u), 2831084092u);
  EXPECT_EQ(pcg_hash(12345u), 4099845390u);
  EXPECT_EQ(pcg_hash(0xffffffffu), 3861530882u);
  EXPECT_EQ(hash2i(3, -7, 42u), 2435244980u);
}

TEST(Noise, HashesSpreadOverNeighbouringCells) {
  std::set<uint32_t> seen;
  for (int y = -20; y < 20; ++y)
    for (int x = -20; x < 20; ++x) seen.insert(hash2i(x, y, 1u));
  EXPECT_EQ(seen.size(), 1600u);
  // pcg3d: changing one input changes all three outputs.
  const glm::uvec3 a = pcg3d(glm::uvec3(1u, 2u, 3u)), b = pcg3d(glm::uvec3(1u, 2u, 4u));
  EXPECT_NE(a.x, b.x);
  EXPECT_NE(a.y, b.y);
  EXPECT_NE(a.z, b.z);
}

TEST(Noise, HashToUnitIsInHalfOpenRange) {
  EXPECT_EQ(hash_to_unit(0u), 0.0f);
  EXPECT_LT(hash_to_unit(0xffffffffu), 1.0f);
  EXPECT_GT(hash_to_unit(0xffffffffu), 0.99999f);
}

TEST(Noise, ValueNoiseInterpolatesLatticeHashes) {
  for (int i = -5; i < 5; ++i) {
    EXPECT_EQ(value_noise(vec2(float(i), 2.0f), 9u), hash_to_unit(hash2i(i, 2, 9u)));
    EXPECT_EQ(value_noise(vec3(1.0f, float(i), -3.0f), 9u), hash_to_unit(hash3i(1, i, -3, 9u)));
  }
}

TEST(Noise, ValueNoiseRangeContinuityAndSeeds) {
  float lo = 1.0f, hi = 0.0f;
  int differs = 0;
  for (int i = 0; i < 20000; ++i) {
    const vec3 p(0.137f * i, 0.071f * i - 300.0f, 0.013f * i);
    const float n = value_noise(p, 3u);
    ASSERT_GE(n, 0.0f);
    ASSERT_LT(n, 1.0f);
    lo = std::min(lo, n);
    hi = std::max(hi, n);
    // Continuous: a 1e-3 step moves the value by at most 1.5 * 1e-3 * sqrt(3) (fade slope 1.5).
    ASSERT_LE(std::abs(value_noise(p + vec3(1e-3f), 3u) - n), 3e-3f);
    if (value_noise(p, 4u) != n) ++differs;
    ASSERT_EQ(value_noise(p, 3u), n);  // deterministic
  }
  EXPECT_LT(lo, 0.1f);  // covers the range
  EXPECT_GT(hi, 0.9f);
  EXPECT_GT(differs, 19000);
}

TEST(Noise, FbmInRangeAndFiniteFarAway) {
  for (int i = 0; i < 5000; ++i) {
    const vec2 p(0.37f * i, -0.11f * i);
    const float f = fbm(p, 5, 1u);
    ASSERT_GE(f, 0.0f);
    ASSERT_LT(f, 1.0f);
    const float g = fbm(vec3(p, 0.5f * i), 4, 1u);
    ASSERT_GE(g, 0.0f);
    ASSERT_LT(g, 1.0f);
  }
  EXPECT_EQ(fbm(vec2(1.5f), 0, 1u), 0.0f);
  EXPECT_TRUE(std::isfinite(fbm(vec3(1e12f, -1e12f, 3e30f), 6, 1u)));
  EXPECT_TRUE(std::isfinite(value_noise(vec2(-1e38f, 1e38f), 1u)));
}

TEST(Noise, WorleyDistancesOrderedAndBounded) {
  for (int i = 0; i < 5000; ++i) {
    const vec2 f2 = worley(vec2(0.173f * i, 0.291f * i - 50.0f), 5u);
    ASSERT_LE(f2.x, f2.y);
    ASSERT_GE(f2.x, 0.0f);
    ASSERT_LT(f2.x, std::sqrt(2.0f));  // the own cell's feature point is within the unit square
    const vec2 f3 = worley(vec3(0.173f * i, 0.291f * i, -0.05f * i), 5u);
    ASSERT_LE(f3.x, f3.y);
    ASSERT_LT(f3.x, std::sqrt(3.0f));
  }
  // F1 is 0 exactly at a feature point.
  const uint32_t h = hash2i(4, -2, 5u);
  const vec2 feature(4.0f + hash_to_unit(h), -2.0f + hash_to_unit(pcg_hash(h)));
  EXPECT_NEAR(worley(feature, 5u).x, 0.0f, 1e-6f);
}

}  // namespace
}  // namespace sdfreel
