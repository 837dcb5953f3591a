// EXR and PNG frame files, encoded in memory (OpenEXR, libpng) and published atomically.
#include "io/frame_files.h"

#include <stdexcept>
#include <vector>

#include "io/atomic_file.h"
#include "io/exr_file.h"
#include "io/png_file.h"
#include "io/png_frames.h"

namespace sdfreel {
namespace {

void check_size(const std::string& path, int width, int height, size_t values, int per_pixel) {
  if (width <= 0 || height <= 0 || values != size_t(width) * height * per_pixel)
    throw std::runtime_error("cannot write " + path +
                             ": image is empty or its size is inconsistent");
}

}  // namespace

void write_exr_atomic(const std::string& path, const ImageRGBA& linear,
                      const std::map<std::string, std::string>& metadata,
                      const ExrSettings& settings, const std::vector<PassImage>& passes) {
  check_size(path, linear.width, linear.height, linear.pixels.size(), 4);
  for (const PassImage& p : passes)
    check_size(path, p.width == linear.width ? p.width : 0,
               p.height == linear.height ? p.height : 0, p.values.size(), int(p.channels.size()));
  std::vector<char> bytes;
  try {
    bytes = encode_exr(linear, metadata, settings, passes);
  } catch (const std::exception& e) {
    throw std::runtime_error("cannot write " + path + ": " + e.what());
  }
  write_file_atomic(path, bytes.data(), bytes.size());
}

void write_png16_atomic(const std::string& path, const ImageRGB16& display) {
  check_size(path, display.width, display.height, display.pixels.size(), 3);
  std::vector<unsigned char> bytes;
  try {
    // The Paeth filter, then Huffman coding only, chosen by measurement on rendered frames
    // (docs/startup-and-io.md, tests/tools/png_levels.cpp): 1.2-1.4x less CPU than zlib level 1
    // with the "up" filter and 7% smaller files; the match search of levels 1-6 costs 1.4-4x
    // the time for 1-10% smaller files. Coded by io/png_frames.h: libpng's bytes, 2.9x faster.
    bytes = encode_png_paeth_huffman(display.width, display.height, 3, 16, display.pixels.data());
  } catch (const std::exception& e) {
    throw std::runtime_error("cannot write " + path + ": " + e.what());
  }
  write_file_atomic(path, bytes.data(), bytes.size());
}

ImageRGB16 read_png16(const std::string& path) {
  PngPixels png = read_png(path, 3);
  ImageRGB16 img;
  img.width = png.width;
  img.height = png.height;
  img.pixels = std::move(png.samples);
  return img;
}

ImageRGBA read_exr(const std::string& path) {
  return read_exr_file(path);
}

void write_text_atomic(const std::string& path, const std::string& contents) {
  write_file_atomic(path, contents);
}

}  // namespace sdfreel
