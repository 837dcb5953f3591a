#pragma once
// A frame in 256 colours, as GIF stores it: a palette made for the frame by median cut over its
// 8-bit RGB (Heckbert's, splitting the most populous box's longest side at its median), and each
// pixel's nearest palette entry. Integer arithmetic and stable orders only, so the same frame
// gives the same bytes everywhere.
#include <array>
#include <cstdint>
#include <vector>

#include "render/image.h"

namespace sdfreel {

struct PalettedImage {
  std::vector<uint8_t> indices;       // one a pixel, row-major, top row first
  std::array<uint32_t, 256> palette;  // 0xAARRGGBB, opaque; unused entries black
};

PalettedImage median_cut_palette(const ImageRGB16& display);

}  // namespace sdfreel
