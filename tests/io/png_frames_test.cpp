// The frame PNGs' own coder against libpng and zlib themselves: the same bytes for images of
// every shape and kind of content, and the same zlib stream for data chosen to reach each of
// zlib's choices (stored, fixed and dynamic blocks, an empty last block, codes over 15 bits cut
// down, small windows).
#include "io/png_frames.h"

#include <gtest/gtest.h>
#include <png.h>
#include <zlib.h>

#include <algorithm>
#include <random>
#include <vector>

#include "io/huffman_deflate.h"
#include "io/png_file.h"

namespace sdfreel {
namespace {

std::vector<uint8_t> zlib_itself(const std::vector<uint8_t>& data, int window_bits) {
  z_stream z{};
  EXPECT_EQ(deflateInit2(&z, 1, Z_DEFLATED, window_bits, 8, Z_HUFFMAN_ONLY), Z_OK);
  std::vector<uint8_t> out(deflateBound(&z, data.size()) + 64);
  z.next_in = const_cast<uint8_t*>(data.data());
  z.avail_in = uInt(data.size());
  z.next_out = out.data();
  z.avail_out = uInt(out.size());
  EXPECT_EQ(deflate(&z, Z_FINISH), Z_STREAM_END);
  out.resize(z.total_out);
  deflateEnd(&z);
  return out;
}

void expect_zlib_bytes(const std::vector<uint8_t>& data, const char* what, int window_bits = 15) {
  EXPECT_EQ(zlib_huffman_only(data.data(), data.size(), window_bits),
            zlib_itself(data, window_bits))
      << what << ", " << data.size() << " bytes, window " << window_bits;
}

TEST(HuffmanDeflate, ZlibsStreamForEveryKindOfBlock) {
  std::mt19937 rng(11);
  auto bytes = [&](size_t n, int spread) {
    std::vector<uint8_t> v(n);
    for (uint8_t& b : v) b = uint8_t(128 + int(rng() % (2 * spread + 1)) - spread);
    return v;
  };
  expect_zlib_bytes({}, "nothing: one empty last block");
  expect_zlib_bytes({42}, "one byte");
  expect_zlib_bytes(std::vector<uint8_t>(1000, 7), "one value only");
  expect_zlib_bytes(bytes(5000, 127), "uniform noise: stored blocks");
  expect_zlib_bytes(bytes(20, 3), "a few bytes: a fixed block");
  expect_zlib_bytes(bytes(100000, 9), "narrow noise: dynamic blocks");
  for (size_t n : {16382, 16383, 16384, 2 * 16383, 2 * 16383 + 1})
    expect_zlib_bytes(bytes(n, 20), "around the block size (16383: an empty last block)");
  for (int w = 9; w <= 15; ++w) expect_zlib_bytes(bytes(3000, 30), "smaller windows", w);
}

TEST(HuffmanDeflate, CodesLongerThanFifteenBitsAreCutAsZlibCutsThem) {
  // Byte values counted 1, 2, 3, 5, 8... (with the end-of-block code's 1) make zlib's tree a
  // chain 18 deep; zlib then moves leaves up to 15 bits.
  std::vector<uint8_t> data;
  uint32_t a = 1, b = 2;
  for (int v = 0; v < 18; ++v) {
    data.insert(data.end(), a, uint8_t(v));
    const uint32_t next = a + b;
    a = b, b = next;
  }
  ASSERT_LE(data.size(), 16383u);  // one block
  std::shuffle(data.begin(), data.end(), std::mt19937(5));
  expect_zlib_bytes(data, "Fibonacci counts");
}

std::vector<unsigned char> libpng_itself(int w, int h, int channels, int depth, const void* px) {
  static_assert(PAETH_HUFFMAN_ONLY.zlib_level == 1 &&
                PAETH_HUFFMAN_ONLY.filter == PNG_FILTER_PAETH &&
                PAETH_HUFFMAN_ONLY.strategy == Z_HUFFMAN_ONLY);
  return encode_png(w, h, channels, depth, px, PAETH_HUFFMAN_ONLY);
}

TEST(PngFrames, LibpngsBytesForEveryShape) {
  std::mt19937 rng(3);
  struct Shape {
    int w, h;
  };
  for (const Shape s : {Shape{1, 1}, {1, 9}, {9, 1}, {2, 2}, {13, 5}, {64, 36}, {126, 129}})
    for (int channels = 1; channels <= 4; ++channels)
      for (int depth : {8, 16}) {
        const size_t n = size_t(s.w) * s.h * channels;
        std::vector<uint16_t> wide(n);
        std::vector<uint8_t> narrow(n);
        for (size_t i = 0; i < n; ++i) wide[i] = uint16_t(rng()), narrow[i] = uint8_t(rng() % 16);
        const void* px = depth == 16 ? static_cast<const void*>(wide.data()) : narrow.data();
        EXPECT_EQ(encode_png_paeth_huffman(s.w, s.h, channels, depth, px),
                  libpng_itself(s.w, s.h, channels, depth, px))
            << s.w << "x" << s.h << ", " << channels << " channels, " << depth << " bits";
      }
}

TEST(PngFrames, LibpngsBytesForAFrameLikePicture) {
  // A 16-bit RGB frame: smooth gradients with fine noise and a flat region, as renders are.
  const int w = 640, h = 360;
  std::mt19937 rng(9);
  std::vector<uint16_t> px(size_t(w) * h * 3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < 3; ++c) {
        const bool flat = x > 400 && y > 200;
        px[(size_t(y) * w + x) * 3 + c] =
            flat ? uint16_t(20000) : uint16_t(x * 90 + y * 40 * (c + 1) + int(rng() % 64));
      }
  EXPECT_EQ(encode_png_paeth_huffman(w, h, 3, 16, px.data()),
            libpng_itself(w, h, 3, 16, px.data()));
}

TEST(PngFrames, RefusesABadSize) {
  const uint16_t px[3] = {};
  EXPECT_THROW(encode_png_paeth_huffman(0, 1, 3, 16, px), std::runtime_error);
  EXPECT_THROW(encode_png_paeth_huffman(1, 1, 5, 16, px), std::runtime_error);
  EXPECT_THROW(encode_png_paeth_huffman(1, 1, 3, 12, px), std::runtime_error);
}

}  // namespace
}  // namespace sdfreel
