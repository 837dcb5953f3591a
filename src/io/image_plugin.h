#pragma once
// Image files of any format OpenImageIO reads, through sdfreel's image module
// (src/plugins/image_oiio), opened with dlopen on the first call: a process that reads no image
// never loads OpenImageIO and its ~250 shared libraries (docs/startup-and-io.md).
#include <string>
#include <vector>

namespace sdfreel {

// An image as its file stores it: `channels` (1-4) interleaved samples a pixel, row 0 at the top.
// For 8- and 16-bit unsigned files (`bits` 8 or 16) the samples are the integer codes (0..255,
// 0..65535) held exactly in floats; for the rest (`bits` 32) they are the file's floats.
struct StoredImage {
  int width = 0, height = 0, channels = 0, bits = 0;
  std::vector<float> samples;
};

// Throws std::runtime_error with the module's or OpenImageIO's message when the file cannot be
// read, or when the module cannot be found or opened.
StoredImage read_stored_image(const std::string& path);

}  // namespace sdfreel
