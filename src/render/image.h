#pragma once
// Linear RGBA float image, row-major, top row first.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace sdfreel {

struct ImageRGBA {
  int width = 0, height = 0;
  std::vector<float> pixels;  // 4 floats per pixel
  ImageRGBA() = default;
  ImageRGBA(int w, int h) : width(w), height(h), pixels(size_t(w) * h * 4, 0.0f) {}
  float* at(int x, int y) { return &pixels[(size_t(y) * width + x) * 4]; }
  const float* at(int x, int y) const { return &pixels[(size_t(y) * width + x) * 4]; }
};

// Display-referred 16-bit RGB, packed like FFmpeg's rgb48le (6 bytes a pixel, no padding).
struct ImageRGB16 {
  int width = 0, height = 0;
  std::vector<uint16_t> pixels;  // 3 per pixel
  ImageRGB16() = default;
  ImageRGB16(int w, int h) : width(w), height(h), pixels(size_t(w) * h * 3, 0) {}
};

}  // namespace sdfreel
