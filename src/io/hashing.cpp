// Frame hashes through libavutil (the same MD5 as FFmpeg's framemd5 muxer).
#include "io/hashing.h"

#include <Imath/half.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <memory>
#include <stdexcept>
#include <vector>

extern "C" {
#include <libavutil/md5.h>
#include <libavutil/mem.h>
}

namespace sdfreel {
namespace {

struct AvFree {
  void operator()(void* p) const { av_free(p); }
};

std::string to_hex(const uint8_t* bytes, size_t n) {
  static const char kDigits[] = "0123456789abcdef";
  std::string out(n * 2, '0');
  for (size_t i = 0; i < n; ++i) {
    out[2 * i] = kDigits[bytes[i] >> 4];
    out[2 * i + 1] = kDigits[bytes[i] & 15];
  }
  return out;
}

// Streams 16-bit values into an MD5 as little-endian bytes, whatever the host's byte order.
class Md5Le16 {
 public:
  Md5Le16() : ctx_(av_md5_alloc()) {
    if (!ctx_) throw std::bad_alloc();
    av_md5_init(ctx_.get());
  }
  void add(uint16_t v) {
    buf_[len_++] = uint8_t(v & 0xff);
    buf_[len_++] = uint8_t(v >> 8);
    if (len_ == sizeof(buf_)) flush();
  }
  std::string hex() {
    flush();
    uint8_t digest[16];
    av_md5_final(ctx_.get(), digest);
    return to_hex(digest, sizeof(digest));
  }

 private:
  void flush() {
    av_md5_update(ctx_.get(), buf_, len_);
    len_ = 0;
  }
  std::unique_ptr<AVMD5, AvFree> ctx_;
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
