#include "io/bit_writer.h"

#include <cstring>
#include <utility>

namespace sdfreel::deflate {

void BitWriter::room(size_t bytes) {
  const size_t need = used_ + bytes + 8;
  if (bytes_.size() < need) bytes_.resize(need > 2 * bytes_.size() ? need : 2 * bytes_.size());
}

void BitWriter::put_each(const uint8_t* data, size_t size, const uint32_t table[256]) {
  uint64_t buffer = buffer_;
  int filled = filled_;
  uint8_t* at = bytes_.data() + used_;
  // Whole bytes out after every three codes (at most 45 bits onto at most 31): eight bytes
  // stored, the pointer moved by those complete. room() left the eight bytes of slack.
  auto spill_bytes = [&] {
#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
    std::memcpy(at, &buffer, 8);
#else
    for (int i = 0; i < 8; ++i) at[i] = uint8_t(buffer >> (8 * i));
#endif
    at += filled >> 3;
    buffer >>= filled & 56;
    filled &= 7;
  };
  auto add = [&](uint8_t b) {
    const uint32_t e = table[b];
    buffer |= uint64_t(e & 0xffff) << filled;
    filled += int(e >> 16);
  };
  spill_bytes();
  size_t i = 0;
  for (; i + 3 <= size; i += 3) {
    add(data[i]);
    add(data[i + 1]);
    add(data[i + 2]);
    spill_bytes();
  }
  for (; i < size; ++i) add(data[i]);
  spill_bytes();
  buffer_ = buffer;
  filled_ = filled;
  used_ = size_t(at - bytes_.data());
}

void BitWriter::align() {
  room(8);
  while (filled_ > 0) {
    bytes_[used_++] = uint8_t(buffer_);
    buffer_ >>= 8;
    filled_ -= 8;
  }
  buffer_ = 0;
  filled_ = 0;
}

std::vector<uint8_t> BitWriter::take() {
  align();
  bytes_.resize(used_);
  used_ = 0;
  return std::move(bytes_);
}

}  // namespace sdfreel::deflate
