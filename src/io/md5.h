#pragma once
// MD5 (RFC 1321), the digest of FFmpeg's framemd5 and of sdfreel's frame hashes: written here so
// that sdfreel itself links no libav library (libavutil loads 18 more at every start).
// tests/io/digests_test.cpp holds it to the RFC's vectors and to libavutil's av_md5.
#include <array>
#include <cstddef>
#include <cstdint>

namespace sdfreel {

class Md5 {
 public:
  void update(const void* data, size_t n);
  std::array<uint8_t, 16> finish();  // the digest; the object is spent

 private:
  void blocks(const uint8_t* p, size_t count);  // whole 64-byte blocks
  uint32_t state_[4] = {0x67452301u, 0xefcdab89u, 0x98badcfeu, 0x10325476u};
  uint64_t length_ = 0;  // bytes so far
  uint8_t buffer_[64] = {};
  size_t buffered_ = 0;
};

}  // namespace sdfreel
