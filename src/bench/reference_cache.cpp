#include "bench/reference_cache.h"

#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <stdexcept>
#include <vector>

#include "io/atomic_file.h"
#include "io/png_file.h"
#include "timeline/sha256.h"

namespace sdfreel::bench {

namespace {

std::string frame_name(const std::string& folder, int frame, const char* kind) {
  char b[32];
  std::snprintf(b, sizeof b, "%05d", frame);
  return folder + "/" + b + kind;
}

// The cached image as 16-bit samples, or nothing when it is missing, unreadable or of another
// size (then the reference is rendered again).
std::optional<std::vector<uint16_t>> read_png_samples(const std::string& path, int w, int h,
                                                      int channels) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) return std::nullopt;
  try {
    PngPixels png = read_png(path, channels);
    if (png.width != w || png.height != h) return std::nullopt;
    return std::move(png.samples);
  } catch (const std::runtime_error&) {
    return std::nullopt;
  }
}

void write_png(const std::string& path, int w, int h, int channels, int bit_depth,
               const void* data) {
  const std::vector<unsigned char> png = encode_png(w, h, channels, bit_depth, data);
  write_file_atomic(path, png.data(), png.size());
}

}  // namespace

std::string reference_key(const std::string& timeline_hash, const std::string& settings, int width,
                          int height) {
  const std::string text = "timeline=" + timeline_hash + "\nsettings=" + settings +
                           "\nsize=" + std::to_string(width) + "x" + std::to_string(height) + "\n";
  return sha256_hex(text);
}

ReferenceCache::ReferenceCache(std::string dir, std::string key)
    : folder_(std::move(dir) + "/reference/" + key.substr(0, 16)) {}

bool ReferenceCache::load(int frame, int width, int height, ImageRGB16& display,
                          ImageRGBA& mask) const {
  auto shown = read_png_samples(frame_name(folder_, frame, ".png"), width, height, 3);
  auto ids = read_png_samples(frame_name(folder_, frame, ".mask.png"), width, height, 1);
  if (!shown || !ids) return false;
  display = ImageRGB16(width, height);
  display.pixels = std::move(*shown);
  mask = ImageRGBA(width, height);
  for (size_t i = 0; i < ids->size(); ++i)
    for (int c = 0; c < 3; ++c) mask.pixels[i * 4 + c] = float((*ids)[i] >> 8);  // 8-bit file
  return true;
}

void ReferenceCache::store(int frame, const ImageRGB16& display, const ImageRGBA& mask) const {
  std::filesystem::create_directories(folder_);
  write_png(frame_name(folder_, frame, ".png"), display.width, display.height, 3, 16,
            display.pixels.data());
  std::vector<uint8_t> ids(size_t(mask.width) * mask.height);
  for (size_t i = 0; i < ids.size(); ++i) {
    const float v = mask.pixels[i * 4];
    if (!(v >= 0.0f && v <= 255.0f) || v != float(int(v)))
      throw std::runtime_error("a hit mask holds a value that is not a hit id");
    ids[i] = uint8_t(v);
  }
  write_png(frame_name(folder_, frame, ".mask.png"), mask.width, mask.height, 1, 8, ids.data());
}

}  // namespace sdfreel::bench
