#pragma once
// Image files of any format OpenImageIO reads or writes, through sdfreel's image module
// (src/plugins/image_oiio), opened with dlopen on the first call: a process that reads no image
// and writes only EXR and PNG never loads OpenImageIO and its ~250 shared libraries
// (docs/startup-and-io.md).
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

// Samples to write: `channels` interleaved a pixel, uint16_t (`sample_bits` 16) or float (32).
struct ImageToWrite {
  int width = 0, height = 0, channels = 0, sample_bits = 16;
  const void* samples = nullptr;
  int file_bits = 0;  // 8, 10, 12, 16 or 32 (float) in the file; 0: as given
  int quality = 0;    // 1-100 for lossy formats; 0: the format's default
};

// Writes `image` to `path` in the format `format_name`'s extension names (`path` may be a
// temporary of another name). Throws std::runtime_error with OpenImageIO's message.
void write_image_file(const std::string& format_name, const std::string& path,
                      const ImageToWrite& image);
// Whether OpenImageIO writes files of this extension (no dot). Throws when the module is missing.
bool image_module_writes(const std::string& extension);

}  // namespace sdfreel
