#pragma once
// A w x h display image of one colour, for tests.
#include <cstdint>

#include "render/image.h"

namespace sdfreel::test {

inline ImageRGB16 solid_frame(int w, int h, uint16_t r, uint16_t g, uint16_t b) {
  ImageRGB16 img(w, h);
  for (size_t i = 0; i < img.pixels.size(); i += 3) {
    img.pixels[i] = r;
    img.pixels[i + 1] = g;
    img.pixels[i + 2] = b;
  }
  return img;
}

}  // namespace sdfreel::test
