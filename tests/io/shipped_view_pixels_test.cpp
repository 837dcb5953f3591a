// The shipped views over rows of pixels, eight at a time in lanes (io/shipped_views.h), give each
// pixel the bits of the one-pixel function: random colours over twelve decades, both signs,
// saturated and grey, the awkward values (zeros, denormals, the largest floats, infinities, NaN),
// a count that leaves a tail of single pixels; alpha is kept.
#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "io/shipped_views.h"

namespace sdfreel {
namespace {

bool same_bits(float a, float b) {
  return std::memcmp(&a, &b, sizeof a) == 0 || (std::isnan(a) && std::isnan(b));
}

std::vector<float> pixels(size_t n) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> decade(-8.0f, 4.0f), unit(0.0f, 1.0f);
  const float inf = std::numeric_limits<float>::infinity();
  const float odd[] = {0.0f,     -0.0f, FLT_TRUE_MIN, FLT_MIN, FLT_MAX,
                       -FLT_MAX, inf,   -inf,         NAN,     0.18f};
  std::vector<float> rgba;
  for (size_t i = 0; i < n; ++i) {
    float c[3];
    for (float& v : c) {
      v = std::pow(10.0f, decade(rng));
      if (unit(rng) < 0.05f) v = -v * 1e-3f;                      // a little below zero
      if (unit(rng) < 0.03f) v = odd[size_t(unit(rng) * 9.99f)];  // awkward
    }
    if (unit(rng) < 0.2f) c[1] = c[2] = c[0];  // grey, where the hue weight is at its edge
    rgba.insert(rgba.end(), {c[0], c[1], c[2], float(i)});
  }
  return rgba;
}

void expect_same_as_one_pixel(const char* view) {
  const ShippedView one = shipped_view("sRGB", view);
  const ShippedViewPixels many = shipped_view_pixels("sRGB", view);
  ASSERT_NE(many, nullptr);
  const size_t n = 100003;  // 12500 groups of eight and a tail of three
  const std::vector<float> in = pixels(n);
  std::vector<float> out = in;
  many(out.data(), n);
  int bad = 0;
  for (size_t i = 0; i < n; ++i) {
    const glm::vec3 want = one({in[i * 4], in[i * 4 + 1], in[i * 4 + 2]});
    for (int c = 0; c < 3; ++c)
      if (!same_bits(out[i * 4 + c], want[c]) && ++bad <= 5)
        ADD_FAILURE() << view << " pixel " << i << " channel " << c << ": " << out[i * 4 + c]
                      << " in lanes, " << want[c] << " alone";
    EXPECT_EQ(out[i * 4 + 3], float(i));
  }
  EXPECT_EQ(bad, 0);
}

TEST(ShippedViewPixels, AcesSdrVideoInLanesHasEachPixelsBits) {
  expect_same_as_one_pixel("ACES 1.0 - SDR Video");
}

TEST(ShippedViewPixels, UntonemappedInLanesHasEachPixelsBits) {
  expect_same_as_one_pixel("Un-tone-mapped");
}

TEST(ShippedViewPixels, OnlyTheShippedViews) {
  EXPECT_EQ(shipped_view_pixels("sRGB", "Filmic"), nullptr);
  EXPECT_EQ(shipped_view_pixels("P3", "ACES 1.0 - SDR Video"), nullptr);
}

}  // namespace
}  // namespace sdfreel
