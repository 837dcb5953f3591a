#pragma once
// The bits of a deflate stream (RFC 1951 3.1.1), least significant first, into bytes it owns.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace sdfreel::deflate {

// put() and byte() write into room made beforehand (room()): the literal loop checks nothing.
class BitWriter {
 public:
  void room(size_t bytes);              // at least this many more bytes can be written
  void put(uint32_t bits, int count) {  // count <= 32
    buffer_ |= uint64_t(bits) << filled_;
    filled_ += count;
    if (filled_ >= 32) {
      uint8_t* p = bytes_.data() + used_;
      p[0] = uint8_t(buffer_), p[1] = uint8_t(buffer_ >> 8), p[2] = uint8_t(buffer_ >> 16),
      p[3] = uint8_t(buffer_ >> 24);
      used_ += 4;
      buffer_ >>= 32;
      filled_ -= 32;
    }
  }
  // A code with its length times 65536 added (deflate_trees.h's BlockCodes entries).
  void put_symbol(uint32_t symbol) { put(symbol & 0xffff, int(symbol >> 16)); }
  // put_symbol(table[data[i]]) for each byte.
  void put_each(const uint8_t* data, size_t size, const uint32_t table[256]);
  void align();                                  // zero bits up to the next byte boundary
  void byte(uint8_t b) { bytes_[used_++] = b; }  // only when aligned
  std::vector<uint8_t> take();                   // aligns, returns the bytes

 private:
  std::vector<uint8_t> bytes_;
  size_t used_ = 0;
  uint64_t buffer_ = 0;
  int filled_ = 0;
};

}  // namespace sdfreel::deflate
