#pragma once
// [output] settings of the frame files (docs/timeline.md#frame-formats): plain values, so that
// the timeline, the manifest and the writers share them.
#include <string>
#include <vector>

namespace sdfreel {

struct FrameFileOptions {
  int tiff_bits = 16;                   // 8 or 16 (display values) or 32 (scene-linear floats)
  int dpx_bits = 10;                    // 8, 10, 12 or 16 (display values)
  int jpeg_quality = 95;                // 1-100
  std::string exr_compression = "piz";  // one of exr_compression_names()
  int exr_bits = 16;                    // 16 (half) or 32 (float)
  std::vector<std::string> passes;      // compositing passes the EXR frames carry, in given order
};

// OpenEXR's compressions by the names [output] exr_compression takes (io/exr_file.cpp maps them):
// lossless none, rle, zips, zip, piz; lossy dwaa, dwab.
inline const std::vector<std::string>& exr_compression_names() {
  static const std::vector<std::string> names = {"none", "rle",  "zips", "zip",
                                                 "piz",  "dwaa", "dwab"};
  return names;
}

}  // namespace sdfreel
