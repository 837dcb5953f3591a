#include "io/huffman_deflate.h"

#include <zlib.h>

#include <algorithm>

#include "io/deflate_trees.h"

namespace sdfreel {

namespace {

constexpr size_t BLOCK_LITERALS = 16383;  // zlib: (lit_bufsize - 1), lit_bufsize 1 << (8 + 6)

// Four tables, summed: a run of one byte value does not wait on its own count's store.
void count_bytes(const uint8_t* data, size_t size, uint32_t counts[256]) {
  uint32_t part[4][256] = {};
  size_t i = 0;
  for (; i + 4 <= size; i += 4) {
    ++part[0][data[i]];
    ++part[1][data[i + 1]];
    ++part[2][data[i + 2]];
    ++part[3][data[i + 3]];
  }
  for (; i < size; ++i) ++part[0][data[i]];
  for (int v = 0; v < 256; ++v) counts[v] = part[0][v] + part[1][v] + part[2][v] + part[3][v];
}

}  // namespace

std::vector<uint8_t> zlib_huffman_only(const uint8_t* data, size_t size, int window_bits) {
  deflate::BitWriter out;
  out.room(size + size / 8 + 64);
  // zlib's header: no preset dictionary, level flags 0 (Huffman only), check bits to 31.
  unsigned header = (Z_DEFLATED + ((unsigned(window_bits) - 8) << 4)) << 8;
  header += 31 - header % 31;
  out.byte(uint8_t(header >> 8));
  out.byte(uint8_t(header));
  size_t at = 0;
  for (;;) {
    const size_t n = std::min(BLOCK_LITERALS, size - at);
    const bool last = n < BLOCK_LITERALS;  // a full block is never the last: zlib flushes it
    uint32_t counts[256];
    count_bytes(data + at, n, counts);
    deflate::BlockCodes codes;
    if (deflate::start_block(out, counts, data + at, n, last, codes)) {
      out.room(2 * n + 8);  // at most 15 bits a literal
      out.put_each(data + at, n, codes.symbol);
      out.put_symbol(codes.symbol[deflate::END_OF_BLOCK]);
    }
    at += n;
    if (last) break;
  }
  out.align();
  const uLong adler = adler32_z(adler32(0L, Z_NULL, 0), data, size);
  for (int shift = 24; shift >= 0; shift -= 8) out.byte(uint8_t(adler >> shift));
  return out.take();
}

}  // namespace sdfreel
