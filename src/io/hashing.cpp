// Frame hashes: the MD5 of FFmpeg's framemd5 muxer (io/md5.h).
#include "io/hashing.h"

#include <Imath/half.h>

#include <array>
#include <memory>

#include "io/md5.h"
#include "render/hex_digest.h"

namespace sdfreel {
namespace {

// Streams 16-bit values into an MD5 as little-endian bytes, whatever the host's byte order.
class Md5Le16 {
 public:
  void add(uint16_t v) {
    buf_[len_++] = uint8_t(v & 0xff);
    buf_[len_++] = uint8_t(v >> 8);
    if (len_ == sizeof(buf_)) flush();
  }
  std::string hex() {
    flush();
    const std::array<uint8_t, 16> digest = md5_.finish();
    return hex_digest(digest.data(), digest.size());
  }

 private:
  void flush() {
    md5_.update(buf_, len_);
    len_ = 0;
  }
  Md5 md5_;
  uint8_t buf_[1 << 16];
  size_t len_ = 0;
};

}  // namespace

std::string md5_rgb48le(const ImageRGB16& display) {
  auto md5 = std::make_unique<Md5Le16>();
  for (uint16_t v : display.pixels) md5->add(v);
  return md5->hex();
}

std::string linear_half_hash(const ImageRGBA& linear) {
  // Imath's float -> half rounds to nearest even, as OpenImageIO does when it writes a half EXR,
  // so this hash is the same for the rendered floats and for the floats read back from the EXR.
  auto md5 = std::make_unique<Md5Le16>();
  for (float v : linear.pixels) md5->add(Imath::half(v).bits());
  return md5->hex();
}

}  // namespace sdfreel
