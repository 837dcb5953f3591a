#pragma once
// PNG encoding and decoding through libpng itself. sdfreel used OpenImageIO for this, which loads
// about 250 shared libraries (OpenCV, DCMTK, OpenVDB, GStreamer...) at every start: half a second
// of CPU before the first pixel. libpng and OpenEXR are all a frame file needs.
#include <cstdint>
#include <string>
#include <vector>

namespace sdfreel {

// How to compress: zlib level (0-9), row filter mask (PNG_FILTER_* of png.h; -1: libpng's
// adaptive default) and zlib strategy (0 default, 1 filtered, 2 Huffman only, 3 RLE).
struct PngCompression {
  int zlib_level = 1;
  int filter = 0x20;  // PNG_FILTER_UP
  int strategy = 0;
};

// Encodes `height` rows of `width` pixels with `channels` interleaved samples (1 gray, 3 RGB, 4
// RGBA), 8-bit (`bit_depth` 8, uint8_t samples) or 16-bit (uint16_t samples in host order), into
// PNG bytes. Throws std::runtime_error.
std::vector<unsigned char> encode_png(int width, int height, int channels, int bit_depth,
                                      const void* samples, const PngCompression& how = {});

struct PngPixels {
  int width = 0, height = 0;
  std::vector<uint16_t> samples;  // width * height * channels, 8-bit files widened (v * 257)
};

// Reads any PNG as `channels` channels (1 gray or 3 RGB): palettes expanded, gray copied to RGB,
// alpha dropped. Throws std::runtime_error naming `path`.
PngPixels read_png(const std::string& path, int channels);

}  // namespace sdfreel
