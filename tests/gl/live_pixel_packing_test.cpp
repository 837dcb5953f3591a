// The packing of an adaptive round's live pixels (backends/gl/live_pixel_packing.h): each
// live pixel gets one slot in the first `rows` rows, the two textures invert each other, stopped
// pixels and unused slots read -1, and eight consecutive live pixels share a 4x2 block.
#include "backends/gl/live_pixel_packing.h"

#include <gtest/gtest.h>

#include <glm/glm.hpp>
#include <set>
#include <utility>

namespace sdfreel {
namespace {

std::vector<uint8_t> pseudo_random_mask(int width, int height, int keep_one_in) {
  std::vector<uint8_t> live(size_t(width) * height);
  uint32_t h = 12345u;
  for (uint8_t& l : live) {
    h = h * 1664525u + 1013904223u;
    l = (h >> 16) % uint32_t(keep_one_in) == 0;
  }
  return live;
}

glm::vec2 texel(const ShaderTexture& t, int x, int y) {
  const float* p = &t.texels[(size_t(y) * t.width + x) * 2];
  return {p[0], p[1]};
}

void expect_a_valid_packing(const std::vector<uint8_t>& live, int width, int height) {
  const LivePixelPacking p = pack_live_pixels(live, width, height, "px", "sl");
  ASSERT_EQ(p.pixels.texels.size(), size_t(width) * height * 2);
  ASSERT_EQ(p.slots.texels.size(), size_t(width) * height * 2);
  EXPECT_LE(p.rows, height);
  std::set<std::pair<int, int>> used;
  int live_count = 0;
  for (int wy = 0; wy < height; ++wy)
    for (int x = 0; x < width; ++x) {
      const glm::vec2 s = texel(p.slots, x, wy);
      if (!live[size_t(height - 1 - wy) * width + x]) {
        EXPECT_EQ(s, glm::vec2(-1.0f)) << x << "," << wy;
        continue;
      }
      ++live_count;
      ASSERT_GE(s.x, 0.0f);
      ASSERT_LT(s.y, float(p.rows)) << "slot outside the drawn rows";
      EXPECT_TRUE(used.insert({int(s.x), int(s.y)}).second) << "slot given twice";
      EXPECT_EQ(texel(p.pixels, int(s.x), int(s.y)), glm::vec2(float(x), float(wy)));
    }
  int slots_with_pixels = 0;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) slots_with_pixels += texel(p.pixels, x, y).x >= 0.0f;
  EXPECT_EQ(slots_with_pixels, live_count);
}

TEST(LivePixelPacking, EveryLivePixelGetsOneSlotBothWays) {
  expect_a_valid_packing(pseudo_random_mask(64, 36, 3), 64, 36);
  expect_a_valid_packing(pseudo_random_mask(37, 11, 2), 37, 11);   // width no multiple of 4
  expect_a_valid_packing(std::vector<uint8_t>(3 * 5, 1), 3, 5);    // narrower than a block
  expect_a_valid_packing(std::vector<uint8_t>(38 * 7, 1), 38, 7);  // too full for blocks
  expect_a_valid_packing(std::vector<uint8_t>(16 * 4, 0), 16, 4);  // nothing live
}

TEST(LivePixelPacking, EightConsecutiveLivePixelsShareA4x2Block) {
  std::vector<uint8_t> live(64 * 36, 0);
  for (int x = 10; x < 26; ++x) live[size_t(5) * 64 + x] = 1;  // 16 pixels of one row
  const LivePixelPacking p = pack_live_pixels(live, 64, 36, "px", "sl");
  EXPECT_EQ(p.rows, 2);
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 8; ++x) {
      const glm::vec2 pixel = texel(p.pixels, x, y);
      // Block 0 holds pixels 10..17, block 1 (x 4..7) pixels 18..25, each row of a block four.
      EXPECT_EQ(pixel.x, float(10 + (x / 4) * 8 + y * 4 + x % 4)) << x << "," << y;
      EXPECT_EQ(pixel.y, float(36 - 1 - 5));
    }
  EXPECT_EQ(texel(p.pixels, 8, 0), glm::vec2(-1.0f));
}

}  // namespace
}  // namespace sdfreel
