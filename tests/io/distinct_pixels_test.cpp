// convert_distinct: the bits of the conversion run on every pixel, with fewer pixels converted
// where values repeat.
#include "io/distinct_pixels.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "io/shipped_views.h"

namespace sdfreel {
namespace {

size_t converted = 0;  // pixels the conversion below was given

// A per-pixel function of RGB that keeps alpha, and tells -0 from +0 and one NaN from another
// (copysign, bit tests), so that a twin found by value instead of by bits would show.
void toy_conversion(float* rgba, size_t n) {
  converted += n;
  for (size_t i = 0; i < n; ++i) {
    float* p = rgba + 4 * i;
    uint32_t bits;
    std::memcpy(&bits, &p[2], sizeof bits);
    const float r = std::copysign(1.0f, p[0]) * std::sqrt(std::fabs(p[0])) + p[1];
    const float g = p[1] * 0.5f - p[2];
    const float b = float(bits & 0xffu) + (std::isnan(p[2]) ? 7.0f : p[2]);
    p[0] = r, p[1] = g, p[2] = b;
  }
}

std::vector<float> frame_like(size_t n, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(-2.0f, 8.0f);
  std::vector<float> px;
  const float nan_a = std::numeric_limits<float>::quiet_NaN();
  float nan_b;
  const uint32_t other_nan = 0x7fc00123u;
  std::memcpy(&nan_b, &other_nan, sizeof nan_b);
  for (size_t i = 0; i < n; ++i) {
    // A flat backdrop (twice, with two alphas); signed zeros and two NaNs; pixels alike in red,
    // or in red and green, only; anything.
    const float any[4] = {u(rng), u(rng), u(rng), u(rng)};
    const float kinds[8][4] = {{0.25f, 0.5f, 1.0f, 1.0f},        {0.25f, 0.5f, 1.0f, 0.5f},
                               {-0.0f, 0.0f, nan_a, 1.0f},       {0.0f, -0.0f, nan_b, 1.0f},
                               {0.25f, any[1], any[2], 1.0f},    {0.25f, 0.5f, any[2], 1.0f},
                               {any[0], any[1], any[2], any[3]}, {any[0], any[1], any[2], any[3]}};
    const float* kind = kinds[rng() % 8];
    px.insert(px.end(), kind, kind + 4);
  }
  return px;
}

void expect_same_as_every_pixel(const std::vector<float>& input, PixelConversion convert) {
  std::vector<float> each = input, once = input;
  convert(each.data(), each.size() / 4);
  convert_distinct(once.data(), once.size() / 4, convert);
  ASSERT_EQ(std::memcmp(each.data(), once.data(), each.size() * sizeof(float)), 0);
}

TEST(DistinctPixels, GivesEveryPixelsOwnConversionsBits) {
  for (uint32_t seed : {1u, 2u, 3u})
    expect_same_as_every_pixel(frame_like(20000, seed), toy_conversion);
  expect_same_as_every_pixel({}, toy_conversion);
}

TEST(DistinctPixels, ConvertsEachRepeatedValueOnce) {
  std::vector<float> flat;
  for (int i = 0; i < 5000; ++i) flat.insert(flat.end(), {0.1f, 0.2f, 0.3f, 1.0f});
  converted = 0;
  convert_distinct(flat.data(), 5000, toy_conversion);
  EXPECT_EQ(converted, 1u);
  std::vector<float> all_different;  // no two pixels share their RGB: every one is converted
  for (int i = 0; i < 5000; ++i)
    all_different.insert(all_different.end(), {float(i), 0.2f, 0.3f, 1.0f});
  converted = 0;
  convert_distinct(all_different.data(), 5000, toy_conversion);
  EXPECT_EQ(converted, 5000u);
}

// The display transform of the shipped config, where it is used: a frame-like buffer of the
// range a render gives (no NaN there), the same bits as the view on every pixel.
TEST(DistinctPixels, TheShippedViewKeepsItsBits) {
  std::vector<float> px = frame_like(30000, 4);
  for (float& v : px)
    if (std::isnan(v)) v = 0.75f;
  for (const char* view : {"ACES 1.0 - SDR Video", "Un-tone-mapped"})
    expect_same_as_every_pixel(px, shipped_view_pixels("sRGB", view));
}

}  // namespace
}  // namespace sdfreel
