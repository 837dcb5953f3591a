// Float -> half as the build does it (Imath::half: F16C's instruction in an AVX2 build, Imath's own
// function in a baseline build) against an independent round-to-nearest-even in double, and the
// 16-bit display quantiser against libm's lround. Frames, EXR files and both hashes rest on these.
#include <Imath/half.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

#include "io/half_image.h"
#include "io/quantise16.h"

namespace sdfreel {
namespace {

float from_bits(uint32_t b) {
  float f;
  std::memcpy(&f, &b, sizeof f);
  return f;
}
uint32_t bits_of(float f) {
  uint32_t b;
  std::memcpy(&b, &f, sizeof b);
  return b;
}

// The half nearest to f, ties to the even one, in exact double arithmetic: the quantum of f's
// binade (at least 2^-24, half's denormal step), nearbyint in the default rounding mode, and
// infinity from 65520 (the midpoint between 65504 and 2^16) up.
float nearest_half(float f) {
  const double a = std::fabs(double(f));
  if (a >= 65520.0) return std::copysign(std::numeric_limits<float>::infinity(), f);
  int e = 0;
  std::frexp(a, &e);  // a = m 2^e, m in [0.5, 1)
  const double quantum = std::ldexp(1.0, std::max(e - 11, -24));
  return float(std::copysign(std::nearbyint(a / quantum) * quantum, double(f)));
}

void expect_rounds_like_the_reference(float f) {
  if (std::isnan(f)) return;
  ASSERT_EQ(bits_of(float(Imath::half(f))), bits_of(nearest_half(f))) << std::hexfloat << f;
}

TEST(HalfRounding, EveryHalfAndItsNeighboursRoundAsTheReference) {
  for (uint32_t h = 0; h < 0x10000; ++h) {
    Imath::half v;
    v.setBits(uint16_t(h));
    if (v.isNan() || v.isInfinity()) continue;
    const uint32_t b = bits_of(float(v));
    for (int d = -2; d <= 2; ++d) expect_rounds_like_the_reference(from_bits(b + uint32_t(d)));
  }
}

// The midpoints between neighbouring halves are floats (12 significant bits): the ties, where a
// rounding that is not to even would show.
TEST(HalfRounding, TiesGoToTheEvenHalf) {
  int ties = 0, up = 0;
  for (uint32_t h = 0; h < 0x7bff; ++h) {  // up to 65504's predecessor, positive and negative
    Imath::half lo, hi;
    lo.setBits(uint16_t(h));
    hi.setBits(uint16_t(h + 1));
    const float mid = float((double(float(lo)) + double(float(hi))) / 2.0);
    ASSERT_EQ(double(mid), (double(float(lo)) + double(float(hi))) / 2.0);
    for (const float m : {mid, -mid}) {
      for (int d = -1; d <= 1; ++d) expect_rounds_like_the_reference(from_bits(bits_of(m) + d));
      ++ties;
    }
    up += Imath::half(mid).bits() == hi.bits();
  }
  EXPECT_EQ(ties, 2 * 0x7bff);
  EXPECT_EQ(up, 0x7bff / 2);  // exactly the ties whose upper neighbour is even
  EXPECT_TRUE(Imath::half(65520.0f).isInfinity());
  EXPECT_EQ(float(Imath::half(65519.996f)), 65504.0f);
}

TEST(HalfRounding, FloatsAcrossTheWholeRangeRoundAsTheReference) {
  for (uint64_t b = 0; b < (uint64_t(1) << 32); b += 65521)  // a prime stride: every exponent
    expect_rounds_like_the_reference(from_bits(uint32_t(b)));
}

TEST(HalfRounding, RoundToHalfClampsThenRounds) {
  ImageRGBA img(2, 1);
  img.pixels = {-1.0f, 0.1f, 70000.0f, 65519.0f, 1e-9f, 3.0e-8f, 0.5f, 1.0f};
  round_to_half(img);
  const std::vector<float> expected = {0.0f, nearest_half(0.1f),    65504.0f, 65504.0f,
                                       0.0f, nearest_half(3.0e-8f), 0.5f,     1.0f};
  EXPECT_EQ(img.pixels, expected);
}

// Every length (the eight-value steps and the rest), every kind of value: the clamp then the
// scalar rounding, bit for bit (-0 stays -0).
TEST(HalfRounding, RoundToHalfGivesTheScalarBitsAtAnyLength) {
  const float kinds[] = {-1.0f,    -0.0f,    0.0f,    1e-9f,     3.0e-8f,  6.1e-5f,
                         0.1f,     0.5f,     1.0f,    2047.5f,   65504.0f, 65519.0f,
                         65520.0f, 70000.0f, 3.4e38f, 1.0009766f};
  for (size_t n = 0; n <= 40; ++n) {
    ImageRGBA img(1, 1);
    img.pixels.clear();
    std::vector<float> expected;
    for (size_t i = 0; i < n; ++i) {
      const float v = kinds[(i * 7 + n) % 16];
      img.pixels.push_back(v);
      expected.push_back(float(Imath::half(v < 0.0f ? 0.0f : std::min(v, 65504.0f))));
    }
    round_to_half(img);
    for (size_t i = 0; i < n; ++i)
      ASSERT_EQ(bits_of(img.pixels[i]), bits_of(expected[i])) << n << " values, at " << i;
  }
}

// quantise16 rounds v * 65535 half away from zero without a libm call: the same integers as
// lround, at every step's boundary and across [0, 1].
TEST(Quantise16, RoundsAsLround) {
  auto reference = [](float v) -> uint16_t {
    if (!(v > 0.0f)) return 0;
    if (v >= 1.0f) return 65535;
    return uint16_t(std::lround(v * 65535.0f));
  };
  for (int k = 0; k < 65535; ++k) {
    const float boundary = (float(k) + 0.5f) / 65535.0f;
    for (int d = -3; d <= 3; ++d) {
      const float v = from_bits(bits_of(boundary) + d);
      ASSERT_EQ(quantise16(v), reference(v)) << std::hexfloat << v;
    }
  }
  for (uint32_t b = 0; b < bits_of(1.0f); b += 251)
    ASSERT_EQ(quantise16(from_bits(b)), reference(from_bits(b)));
  EXPECT_EQ(quantise16(std::numeric_limits<float>::quiet_NaN()), 0);
  EXPECT_EQ(quantise16(2.0f), 65535);
  EXPECT_EQ(quantise16(-0.5f), 0);
}

}  // namespace
}  // namespace sdfreel
