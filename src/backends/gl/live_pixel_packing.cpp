#include "backends/gl/live_pixel_packing.h"

#include <algorithm>
#include <glm/glm.hpp>

namespace sdfreel {

namespace {

// Window position of slot k: 4x2 blocks of eight slots, blocks left to right then upwards; a frame
// too narrow for blocks, or too full for them when its width is no multiple of 4, goes row by row.
struct SlotLayout {
  int width, blocks_a_row;
  glm::ivec2 at(int k) const {
    if (blocks_a_row == 0) return {k % width, k / width};
    const int block = k / 8, i = k % 8;
    return {4 * (block % blocks_a_row) + i % 4, 2 * (block / blocks_a_row) + i / 4};
  }
  int rows(int count) const {
    if (count == 0) return 0;
    if (blocks_a_row == 0) return (count + width - 1) / width;
    const int per_band = 8 * blocks_a_row;
    return 2 * ((count + per_band - 1) / per_band);
  }
};

ShaderTexture texture(const char* name, int width, int height) {
  return ShaderTexture{name, width, height, 2,
                       std::vector<float>(size_t(width) * height * 2, -1.0f)};
}

}  // namespace

LivePixelPacking pack_live_pixels(const std::vector<uint8_t>& live, int width, int height,
                                  const char* pixels_name, const char* slots_name) {
  const int count = int(std::count(live.begin(), live.end(), uint8_t(1)));
  SlotLayout layout{width, width / 4};
  if (layout.rows(count) > height) layout.blocks_a_row = 0;
  LivePixelPacking p{texture(pixels_name, width, height), texture(slots_name, width, height),
                     layout.rows(count)};
  int k = 0;
  for (int wy = 0; wy < height; ++wy)
    for (int x = 0; x < width; ++x) {
      if (!live[size_t(height - 1 - wy) * width + x]) continue;
      const glm::ivec2 s = layout.at(k++);
      float* pixel = &p.pixels.texels[(size_t(s.y) * width + s.x) * 2];
      pixel[0] = float(x);
      pixel[1] = float(wy);
      float* slot = &p.slots.texels[(size_t(wy) * width + x) * 2];
      slot[0] = float(s.x);
      slot[1] = float(s.y);
    }
  return p;
}

}  // namespace sdfreel
