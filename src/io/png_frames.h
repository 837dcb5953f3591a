#pragma once
// The frame files' PNG coding (the Paeth filter on every row, then zlib's Huffman-only coding at
// level 1), written here instead of through libpng: the same bytes as libpng 1.6 with zlib
// (tests/io/png_frames_test.cpp compares them), in a third of the time. The filtering has no
// chain from byte to byte and the compiler vectorises it; the coding is io/huffman_deflate.h.
// libpng's choices are kept: no filter when the image is one row or one column high, the window
// lowered for data under 16 KiB, IDAT chunks of 8192 bytes.
#include <cstdint>
#include <vector>

#include "io/png_file.h"

namespace sdfreel {

// The libpng setting whose bytes this coder writes: zlib level 1, PNG_FILTER_PAETH (0x80),
// Z_HUFFMAN_ONLY (2).
constexpr PngCompression PAETH_HUFFMAN_ONLY{1, 0x80, 2};

// encode_png(width, height, channels, bit_depth, samples, PAETH_HUFFMAN_ONLY)'s bytes: `channels` 1
// to 4, `bit_depth` 8 (uint8_t samples) or 16 (uint16_t samples in host order). Throws
// std::runtime_error on a bad size.
std::vector<unsigned char> encode_png_paeth_huffman(int width, int height, int channels,
                                                    int bit_depth, const void* samples);

}  // namespace sdfreel
