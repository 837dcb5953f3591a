#pragma once
// PNG encoding and decoding through libpng itself. sdfreel used OpenImageIO for this, which loads
// about 250 shared libraries (OpenCV, DCMTK, OpenVDB, GStreamer...) at every start: half a second
// of CPU before the first pixel. libpng and OpenEXR are all a frame file needs.
#include <cstdint>
#include <string>
#include <vector>

namespace sdfreel {

// zlib level and row filter of frame PNGs, chosen by measurement (docs/startup-and-io.md): level 1
// with the "up" filter is the fastest and, on rendered frames, about as small as level 6.
constexpr int kPngFrameZlibLevel = 1;

// Encodes `height` rows of `width` pixels with `channels` interleaved samples (1 gray, 3 RGB, 4
// RGBA), 8-bit (`bit_depth` 8, uint8_t samples) or 16-bit (uint16_t samples in host order), into
// PNG bytes. `filter` is a PNG_FILTER_* mask (0 = libpng's default). Throws std::runtime_error.
std::vector<unsigned char> encode_png(int width, int height, int channels, int bit_depth,
                                      const void* samples, int zlib_level = kPngFrameZlibLevel,
                                      int filter = -1);

struct PngPixels {
  int width = 0, height = 0;
  std::vector<uint16_t> samples;  // width * height * channels, 8-bit files widened (v * 257)
};

// Reads any PNG as `channels` channels (1 gray or 3 RGB): palettes expanded, gray copied to RGB,
// alpha dropped. Throws std::runtime_error naming `path`.
PngPixels read_png(const std::string& path, int channels);

}  // namespace sdfreel
