#include "io/md5.h"

#include <cstring>
#include <utility>

namespace sdfreel {

namespace {

constexpr uint32_t K[64] = {
    0xd76aa478, 0xe8c7b756, 0x242070db, 0xc1bdceee, 0xf57c0faf, 0x4787c62a, 0xa8304613, 0xfd469501,
    0x698098d8, 0x8b44f7af, 0xffff5bb1, 0x895cd7be, 0x6b901122, 0xfd987193, 0xa679438e, 0x49b40821,
    0xf61e2562, 0xc040b340, 0x265e5a51, 0xe9b6c7aa, 0xd62f105d, 0x02441453, 0xd8a1e681, 0xe7d3fbc8,
    0x21e1cde6, 0xc33707d6, 0xf4d50d87, 0x455a14ed, 0xa9e3e905, 0xfcefa3f8, 0x676f02d9, 0x8d2a4c8a,
    0xfffa3942, 0x8771f681, 0x6d9d6122, 0xfde5380c, 0xa4beea44, 0x4bdecfa9, 0xf6bb4b60, 0xbebfbc70,
    0x289b7ec6, 0xeaa127fa, 0xd4ef3085, 0x04881d05, 0xd9d4d039, 0xe6db99e5, 0x1fa27cf8, 0xc4ac5665,
    0xf4292244, 0x432aff97, 0xab9423a7, 0xfc93a039, 0x655b59c3, 0x8f0ccc92, 0xffeff47d, 0x85845dd1,
    0x6fa87e4f, 0xfe2ce6e0, 0xa3014314, 0x4e0811a1, 0xf7537e82, 0xbd3af235, 0x2ad7d2bb, 0xeb86d391};
constexpr int SHIFT[4][4] = {{7, 12, 17, 22}, {5, 9, 14, 20}, {4, 11, 16, 23}, {6, 10, 15, 21}};

uint32_t rotl(uint32_t x, int s) {
  return (x << s) | (x >> (32 - s));
}

uint32_t le32(const uint8_t* p) {
  return uint32_t(p[0]) | uint32_t(p[1]) << 8 | uint32_t(p[2]) << 16 | uint32_t(p[3]) << 24;
}

// Step i of the 64: the round's function and word, then the four words turn one place (with the
// steps unrolled at compile time, the turn is a renaming of registers).
template <int i>
void step(uint32_t& a, uint32_t& b, uint32_t& c, uint32_t& d, const uint32_t* m) {
  uint32_t f;
  if constexpr (i < 16)
    f = (b & c) | (~b & d);
  else if constexpr (i < 32)
    f = (d & b) | (~d & c);
  else if constexpr (i < 48)
    f = b ^ c ^ d;
  else
    f = c ^ (b | ~d);
  constexpr int g = i < 16   ? i
                    : i < 32 ? (5 * i + 1) & 15
                    : i < 48 ? (3 * i + 5) & 15
                             : (7 * i) & 15;
  const uint32_t next = b + rotl(a + f + K[i] + m[g], SHIFT[i / 16][i & 3]);
  a = d, d = c, c = b, b = next;
}

template <size_t... I>
void compress(uint32_t (&state)[4], const uint32_t* m, std::index_sequence<I...>) {
  uint32_t a = state[0], b = state[1], c = state[2], d = state[3];
  (step<int(I)>(a, b, c, d, m), ...);
  state[0] += a, state[1] += b, state[2] += c, state[3] += d;
}

}  // namespace

void Md5::blocks(const uint8_t* p, size_t count) {
  for (; count > 0; --count, p += 64) {
    uint32_t m[16];
    for (int i = 0; i < 16; ++i) m[i] = le32(p + 4 * i);
    compress(state_, m, std::make_index_sequence<64>());
  }
}

void Md5::update(const void* data, size_t n) {
  const auto* p = static_cast<const uint8_t*>(data);
  length_ += n;
  if (buffered_ > 0) {
    const size_t take = n < 64 - buffered_ ? n : 64 - buffered_;
    std::memcpy(buffer_ + buffered_, p, take);
    buffered_ += take, p += take, n -= take;
    if (buffered_ < 64) return;
    blocks(buffer_, 1);
    buffered_ = 0;
  }
  blocks(p, n / 64);
  std::memcpy(buffer_, p + n / 64 * 64, n % 64);
  buffered_ = n % 64;
}

std::array<uint8_t, 16> Md5::finish() {
  const uint64_t bits = length_ * 8;
  uint8_t pad[72] = {0x80};
  const size_t zeros = (buffered_ < 56 ? 56 : 120) - buffered_;
  for (int i = 0; i < 8; ++i) pad[zeros + size_t(i)] = uint8_t(bits >> (8 * i));
  update(pad, zeros + 8);
  std::array<uint8_t, 16> digest;
  for (int i = 0; i < 16; ++i) digest[size_t(i)] = uint8_t(state_[i / 4] >> (8 * (i % 4)));
  return digest;
}

}  // namespace sdfreel
