#pragma once
// One chunk of OpenEXR's PIZ compression (PizCompressor::compress, 3.1): the values in use
// renumbered densely through a bitmap (stored), each channel's 2D wavelet (io/exr_wavelet.h), then
// Huffman coding (io/exr_huffman.h). The same bytes as OpenEXR (tests/io/exr_piz_test.cpp).
#include <cstdint>
#include <vector>

namespace sdfreel {

// A channel of a chunk: `ny` rows of `nx * words` 16-bit words (a half is one word, a float or
// uint two, low word first), stored after the channel before it.
struct PizChannel {
  int nx, ny, words;
};

// The chunk's compressed bytes; `values` (every channel's words, in order) is changed in place.
std::vector<char> piz_compress(std::vector<uint16_t>& values,
                               const std::vector<PizChannel>& channels);

}  // namespace sdfreel
