#pragma once
// The card's texel reads on eight lanes (front_colour's print texel and ridge normal), with the
// operations of the one-ray reads in card_shading.h lane by lane, so the same bits: wrap_texel's
// modulo, sampleBilinear's weights, the strips' byte layout and decode table (textures.h).
#include "scenes/common/texture.h"
#include "scenes/lenticular_card/textures.h"
#include "sdf/lanes.h"

namespace sdfreel::lenticular_card {

// wrap_texel(x, n) in each lane: x - n * floor(x / n), truncated to an integer.
inline M8 wrap_texels(F8 x, int n) {
  const F8 size = splat(float(n));
  return __builtin_convertvector(x - size * dm::floor(x / size), M8);
}

// Indices outside [0, n) (lanes whose ray missed the face, never shown) read entry 0.
inline M8 in_range(M8 i, int n) {
  return i & ((i >= 0) & (i < n));
}

// print.texel(wrap_texel(column, width), wrap_texel(row, height)).rgb in each lane.
inline V3x8 print_texels(const StripPrint& print, F8 column, F8 row) {
  const M8 x = wrap_texels(column, print.width), y = wrap_texels(row, print.height);
  // x / views and x % views in floats: exact for integers this small.
  const F8 xf = __builtin_convertvector(x, F8), views = splat(float(print.views));
  const F8 lens = dm::floor(xf / views);
  const M8 strip = __builtin_convertvector(xf - lens * views, M8);
  const M8 i =
      (strip * print.height + y) * (print.width / print.views) + __builtin_convertvector(lens, M8);
  const int texels = int(print.rgbx.size() / 4);
  const M8 word = gather(reinterpret_cast<const int32_t*>(print.rgbx.data()), in_range(i, texels));
  const float* decode = print.decode.data();
  return V3x8(gather(decode, word & 255), gather(decode, (word >> 8) & 255),
              gather(decode, (word >> 16) & 255));
}

// sampleBilinear(t, (u, v)).xy in each lane (t of two channels or more).
inline V2x8 bilinear_xy(const Texture& t, F8 u, F8 v) {
  const F8 x = u * float(t.width) - 0.5f, y = v * float(t.height) - 0.5f;
  const F8 x0 = dm::floor(x), y0 = dm::floor(y);
  const F8 fx = x - x0, fy = y - y0;
  const M8 c0 = wrap_texels(x0, t.width), c1 = wrap_texels(x0 + 1.0f, t.width);
  const M8 r0 = wrap_texels(y0, t.height), r1 = wrap_texels(y0 + 1.0f, t.height);
  const int size = t.width * t.height;
  const auto at = [&](M8 column, M8 row) {
    return in_range(row * t.width + column, size) * t.channels;
  };
  const M8 a = at(c0, r0), b = at(c1, r0), c = at(c0, r1), d = at(c1, r1);
  const auto channel = [&](int k) {
    const float* texels = t.texels.data() + k;
    const F8 ab = gather(texels, a) * (1.0f - fx) + gather(texels, b) * fx;
    const F8 cd = gather(texels, c) * (1.0f - fx) + gather(texels, d) * fx;
    return ab * (1.0f - fy) + cd * fy;
  };
  return V2x8{channel(0), channel(1)};
}

}  // namespace sdfreel::lenticular_card
