#include "io/display_referred.h"

#include <cmath>

namespace sdfreel {

namespace {

uint16_t quantise(float v) {
  if (!(v > 0.0f)) return 0;  // NaN too
  if (v >= 1.0f) return 65535;
  return uint16_t(std::lround(v * 65535.0f));
}

float decode(float v) {
  if (!(v > 0.0f)) return 0.0f;
  return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f);
}

}  // namespace

ImageRGB16 quantised_display(const ImageRGBA& display) {
  ImageRGB16 out(display.width, display.height);
  const size_t n = size_t(display.width) * size_t(display.height);
  for (size_t i = 0; i < n; ++i)
    for (size_t c = 0; c < 3; ++c) out.pixels[3 * i + c] = quantise(display.pixels[4 * i + c]);
  return out;
}

ImageRGBA srgb_decoded(const ImageRGBA& display) {
  ImageRGBA out = display;
  const size_t n = size_t(display.width) * size_t(display.height);
  for (size_t i = 0; i < n; ++i)
    for (size_t c = 0; c < 3; ++c) out.pixels[4 * i + c] = decode(display.pixels[4 * i + c]);
  return out;
}

}  // namespace sdfreel
