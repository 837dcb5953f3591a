// first_pixel_diff A.png B.png: exit 0 when the two 16-bit PNGs hold the same pixels, else prints
// the size difference or the first differing pixel (row-major) and its values, exit 1. Used by
// scripts/build-matrix.sh to name where two builds' frames part.
#include <cstdio>
#include <exception>

#include "io/frame_files.h"

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: first_pixel_diff A.png B.png\n");
    return 2;
  }
  try {
    const sdfreel::ImageRGB16 a = sdfreel::read_png16(argv[1]), b = sdfreel::read_png16(argv[2]);
    if (a.width != b.width || a.height != b.height) {
      std::printf("sizes differ: %dx%d vs %dx%d\n", a.width, a.height, b.width, b.height);
      return 1;
    }
    for (size_t i = 0; i < a.pixels.size(); i += 3) {
      if (a.pixels[i] == b.pixels[i] && a.pixels[i + 1] == b.pixels[i + 1] &&
          a.pixels[i + 2] == b.pixels[i + 2])
        continue;
      const size_t p = i / 3;
      std::printf("first differing pixel (x %zu, y %zu): rgb16 (%u, %u, %u) vs (%u, %u, %u)\n",
                  p % size_t(a.width), p / size_t(a.width), a.pixels[i], a.pixels[i + 1],
                  a.pixels[i + 2], b.pixels[i], b.pixels[i + 1], b.pixels[i + 2]);
      return 1;
    }
    std::printf("same pixels\n");
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "first_pixel_diff: %s\n", e.what());
    return 2;
  }
}
