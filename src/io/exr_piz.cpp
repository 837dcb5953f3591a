#include "io/exr_piz.h"

#include "io/exr_huffman.h"
#include "io/exr_wavelet.h"
#include "io/little_endian.h"

namespace sdfreel {

namespace {

constexpr int BITMAP_BYTES = (1 << 16) / 8;

}  // namespace

std::vector<char> piz_compress(std::vector<uint16_t>& values,
                               const std::vector<PizChannel>& channels) {
  // The values in use; zero is taken as always there and not stored.
  // Odd positions marked apart: a run of one value would otherwise wait on each byte's update.
  std::vector<uint8_t> bitmap(BITMAP_BYTES), odd(BITMAP_BYTES);
  size_t k = 0;
  for (; k + 2 <= values.size(); k += 2) {
    bitmap[values[k] >> 3] |= uint8_t(1 << (values[k] & 7));
    odd[values[k + 1] >> 3] |= uint8_t(1 << (values[k + 1] & 7));
  }
  if (k < values.size()) bitmap[values[k] >> 3] |= uint8_t(1 << (values[k] & 7));
  for (int i = 0; i < BITMAP_BYTES; ++i) bitmap[size_t(i)] |= odd[size_t(i)];
  bitmap[0] &= uint8_t(~1);
  int first = BITMAP_BYTES - 1, last = 0;
  for (int i = 0; i < BITMAP_BYTES; ++i)
    if (bitmap[size_t(i)]) {
      first = first > i ? i : first;
      last = i;
    }
  // Each value in use renumbered by its rank among them (zero first); entries of values absent
  // are never read, so the table is kept per thread and never cleared.
  thread_local std::vector<uint16_t> rank(1 << 16);
  int next = 1;
  rank[0] = 0;
  for (int i = first; i <= last; ++i)
    for (unsigned bits = bitmap[size_t(i)]; bits; bits &= bits - 1)
      rank[size_t(i * 8 + __builtin_ctz(bits))] = uint16_t(next++);
  const auto max_rank = uint16_t(next - 1);
  for (uint16_t& v : values) v = rank[v];

  std::vector<char> out;
  out.reserve(values.size() + BITMAP_BYTES);
  append_le(out, uint32_t(first), 2);
  append_le(out, uint32_t(last), 2);
  if (first <= last) out.insert(out.end(), bitmap.begin() + first, bitmap.begin() + last + 1);

  uint16_t* channel = values.data();
  for (const PizChannel& c : channels) {
    for (int w = 0; w < c.words; ++w)
      exr_wavelet_encode(channel + w, c.nx, c.words, c.ny, c.nx * c.words, max_rank);
    channel += size_t(c.nx) * size_t(c.ny) * size_t(c.words);
  }

  const size_t length_at = out.size();
  append_le(out, 0, 4);
  const size_t length = exr_huffman_compress(values.data(), values.size(), out);
  store_le(&out[length_at], length, 4);
  return out;
}

}  // namespace sdfreel
