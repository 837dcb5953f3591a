#include "bench/reference_cache.h"

#include <OpenImageIO/imageio.h>

#include <cstdio>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <vector>

#include "io/image_write.h"
#include "timeline/sha256.h"

namespace sdfreel::bench {

namespace {

std::string frame_name(const std::string& folder, int frame, const char* kind) {
  char b[32];
  std::snprintf(b, sizeof b, "%05d", frame);
  return folder + "/" + b + kind;
}

bool read_png(const std::string& path, int w, int h, int channels, OIIO::TypeDesc type,
              void* data) {
  auto in = OIIO::ImageInput::open(path);
  if (!in) return false;
  const OIIO::ImageSpec& spec = in->spec();
  if (spec.width != w || spec.height != h || spec.nchannels != channels) return false;
  return in->read_image(0, 0, 0, channels, type, data);
}

void write_png(const std::string& path, int w, int h, int channels, OIIO::TypeDesc type,
               const void* data) {
  write_image_atomic(path, "png", OIIO::ImageSpec(w, h, channels, type), type, data);
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
  ImageRGB16 d(width, height);
  std::vector<uint8_t> ids(size_t(width) * height);
  if (!read_png(frame_name(folder_, frame, ".png"), width, height, 3, OIIO::TypeDesc::UINT16,
                d.pixels.data()) ||
      !read_png(frame_name(folder_, frame, ".mask.png"), width, height, 1, OIIO::TypeDesc::UINT8,
                ids.data()))
    return false;
  display = std::move(d);
  mask = ImageRGBA(width, height);
  for (size_t i = 0; i < ids.size(); ++i)
    for (int c = 0; c < 3; ++c) mask.pixels[i * 4 + c] = float(ids[i]);
  return true;
}

void ReferenceCache::store(int frame, const ImageRGB16& display, const ImageRGBA& mask) const {
  std::filesystem::create_directories(folder_);
  write_png(frame_name(folder_, frame, ".png"), display.width, display.height, 3,
            OIIO::TypeDesc::UINT16, display.pixels.data());
  std::vector<uint8_t> ids(size_t(mask.width) * mask.height);
  for (size_t i = 0; i < ids.size(); ++i) {
    const float v = mask.pixels[i * 4];
    if (!(v >= 0.0f && v <= 255.0f) || v != float(int(v)))
      throw std::runtime_error("a hit mask holds a value that is not a hit id");
    ids[i] = uint8_t(v);
  }
  write_png(frame_name(folder_, frame, ".mask.png"), mask.width, mask.height, 1,
            OIIO::TypeDesc::UINT8, ids.data());
}

}  // namespace sdfreel::bench
