// The strand hash: distinct for every cell of a large grid (negative cells included), unlike the
// x + 100 * y seed it replaces, and its strand values spread over [0, 1).
#include "scenes/fur/strand_hash.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <vector>

namespace sdfreel::fur {
namespace {

constexpr int HALF = 1024;  // cells -1024..1023 on each axis: 4 Mi cells

uint64_t key(const glm::uvec2& h) {
  return (uint64_t(h.x) << 32u) | h.y;
}

TEST(StrandHash, NoTwoCellsOfALargeGridCollide) {
  std::vector<uint64_t> keys;
  keys.reserve(size_t(4 * HALF * HALF));
  for (int y = -HALF; y < HALF; ++y)
    for (int x = -HALF; x < HALF; ++x)
      keys.push_back(key(pcg2d(glm::uvec2(uint32_t(x), uint32_t(y)))));
  std::sort(keys.begin(), keys.end());
  EXPECT_EQ(std::adjacent_find(keys.begin(), keys.end()), keys.end());
}

TEST(StrandHash, TheCommonSeedCollidesWhereThisDoesNot) {
  // Density 366 (Acerola's demo): cell (x + 100, y) and (x, y + 1) share x + 100 * y.
  EXPECT_EQ(150 + 100 * 7, 50 + 100 * 8);
  EXPECT_NE(key(pcg2d({150u, 7u})), key(pcg2d({50u, 8u})));
  EXPECT_NE(strand_random(150, 7), strand_random(50, 8));
}

TEST(StrandHash, StrandValuesSpreadOverTheUnitInterval) {
  int bins[10] = {};
  for (int y = 0; y < 200; ++y)
    for (int x = 0; x < 200; ++x) {
      const float r = strand_random(x, y);
      ASSERT_GE(r, 0.0f);
      ASSERT_LT(r, 1.0f);
      ++bins[int(r * 10.0f)];
    }
  for (int b : bins) EXPECT_NEAR(b, 4000, 300);  // 40000 values, about 4000 per tenth
}

}  // namespace
}  // namespace sdfreel::fur
