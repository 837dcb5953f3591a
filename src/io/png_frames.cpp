#include "io/png_frames.h"

#include <zlib.h>

#include <algorithm>
#include <cstring>
#include <stdexcept>

#include "io/huffman_deflate.h"

namespace sdfreel {

namespace {

constexpr size_t IDAT_BYTES = 8192;  // libpng's PNG_ZBUF_SIZE: one IDAT per full zlib buffer

// Row `y` as PNG stores it: 16-bit samples big-endian.
void stored_row(const void* samples, int y, size_t row_bytes, int bit_depth, uint8_t* row) {
  const uint8_t* from = static_cast<const uint8_t*>(samples) + size_t(y) * row_bytes;
  if (bit_depth == 8) {
    std::memcpy(row, from, row_bytes);
    return;
  }
  for (size_t i = 0; i < row_bytes; i += 2) row[i] = from[i + 1], row[i + 1] = from[i];
}

// The Paeth predictor's filter (PNG 9.4) as libpng's png_setup_paeth_row_only computes it.
// No byte depends on another's result: GCC and Clang vectorise the loop.
void paeth_row(const uint8_t* row, const uint8_t* prev, size_t row_bytes, size_t bpp,
               uint8_t* out) {
  for (size_t i = 0; i < bpp && i < row_bytes; ++i) out[i] = uint8_t(row[i] - prev[i]);
  for (size_t i = bpp; i < row_bytes; ++i) {
    const int a = row[i - bpp], b = prev[i], c = prev[i - bpp];
    const int p = b - c, q = a - c;
    const int pa = p < 0 ? -p : p, pb = q < 0 ? -q : q, pc = p + q < 0 ? -(p + q) : p + q;
    const int predicted = (pa <= pb && pa <= pc) ? a : (pb <= pc) ? b : c;
    out[i] = uint8_t(row[i] - predicted);
  }
}

void put_u32(std::vector<unsigned char>& out, uint32_t v) {
  for (int shift = 24; shift >= 0; shift -= 8) out.push_back(uint8_t(v >> shift));
}

void put_chunk(std::vector<unsigned char>& out, const char type[4], const uint8_t* data,
               size_t size) {
  put_u32(out, uint32_t(size));
  const size_t at = out.size();
  out.insert(out.end(), type, type + 4);
  out.insert(out.end(), data, data + size);
  put_u32(out, uint32_t(crc32_z(0L, out.data() + at, size + 4)));
}

// libpng's png_deflate_claim: the window halved while data plus zlib's 262-byte lookahead fit.
int window_bits_for(size_t data_size) {
  int bits = 15;
  if (data_size <= 16384)
    for (size_t half = size_t(1) << (bits - 1); data_size + 262 <= half; half >>= 1) --bits;
  return bits;
}

// libpng's optimize_cmf: the header's window field lowered further to what the data needs.
void optimise_header(uint8_t* header, size_t data_size) {
  if (data_size > 16384) return;
  unsigned cinfo = header[0] >> 4;
  size_t half = size_t(1) << (cinfo + 7);
  if (data_size > half) return;
  do {
    half >>= 1;
    --cinfo;
  } while (cinfo > 0 && data_size <= half);
  header[0] = uint8_t((header[0] & 0x0f) | (cinfo << 4));
  unsigned flags = header[1] & 0xe0u;
  flags += 0x1f - ((unsigned(header[0]) << 8) + flags) % 0x1f;
  header[1] = uint8_t(flags);
}

}  // namespace

std::vector<unsigned char> encode_png_paeth_huffman(int width, int height, int channels,
                                                    int bit_depth, const void* samples) {
  if (width <= 0 || height <= 0 || channels < 1 || channels > 4 ||
      (bit_depth != 8 && bit_depth != 16))
    throw std::runtime_error("PNG: bad image size or bit depth");
  const size_t bpp = size_t(channels) * size_t(bit_depth / 8);
  const size_t row_bytes = size_t(width) * bpp;
  // libpng drops filters that need the row above or the pixel to the left when there is none.
  const bool paeth = width > 1 && height > 1;
  std::vector<uint8_t> filtered(size_t(height) * (row_bytes + 1));
  std::vector<uint8_t> row(row_bytes), prev(row_bytes, 0);
  for (int y = 0; y < height; ++y) {
    uint8_t* out = &filtered[size_t(y) * (row_bytes + 1)];
    stored_row(samples, y, row_bytes, bit_depth, row.data());
    out[0] = paeth ? 4 : 0;
    if (paeth)
      paeth_row(row.data(), prev.data(), row_bytes, bpp, out + 1);
    else
      std::memcpy(out + 1, row.data(), row_bytes);
    std::swap(row, prev);
  }
  std::vector<uint8_t> z =
      zlib_huffman_only(filtered.data(), filtered.size(), window_bits_for(filtered.size()));
  optimise_header(z.data(), filtered.size());

  std::vector<unsigned char> png = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  png.reserve(z.size() + z.size() / IDAT_BYTES * 12 + 64);
  uint8_t ihdr[13];
  for (int i = 0; i < 4; ++i) {
    ihdr[i] = uint8_t(uint32_t(width) >> (24 - 8 * i));
    ihdr[4 + i] = uint8_t(uint32_t(height) >> (24 - 8 * i));
  }
  const uint8_t colour_types[] = {0, 4, 2, 6};  // gray, gray + alpha, RGB, RGBA
  ihdr[8] = uint8_t(bit_depth), ihdr[9] = colour_types[channels - 1];
  ihdr[10] = ihdr[11] = ihdr[12] = 0;  // deflate, adaptive filtering, no interlace
  put_chunk(png, "IHDR", ihdr, sizeof ihdr);
  for (size_t at = 0; at < z.size(); at += IDAT_BYTES)
    put_chunk(png, "IDAT", z.data() + at, std::min(IDAT_BYTES, z.size() - at));
  put_chunk(png, "IEND", nullptr, 0);
  return png;
}

}  // namespace sdfreel
