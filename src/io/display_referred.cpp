#include "io/display_referred.h"

#include "io/quantise16.h"
#include "render/srgb.h"

namespace sdfreel {

ImageRGB16 quantised_display(const ImageRGBA& display) {
  ImageRGB16 out(display.width, display.height);
  const size_t n = size_t(display.width) * size_t(display.height);
  for (size_t i = 0; i < n; ++i)
    for (size_t c = 0; c < 3; ++c) out.pixels[3 * i + c] = quantise16(display.pixels[4 * i + c]);
  return out;
}

ImageRGBA srgb_decoded(const ImageRGBA& display) {
  ImageRGBA out = display;
  const size_t n = size_t(display.width) * size_t(display.height);
  for (size_t i = 0; i < n; ++i)
    for (size_t c = 0; c < 3; ++c)
      out.pixels[4 * i + c] = srgb_to_linear(display.pixels[4 * i + c]);
  return out;
}

}  // namespace sdfreel
