#pragma once
// OpenEXR's Huffman coding of 16-bit values (the last step of PIZ), written here so that a frame's
// EXR chunks code side by side on sdfreel's threads: the same bytes as OpenEXR 3.1's hufCompress
// (tests/io/exr_piz_test.cpp compares them). Its stream: five little-endian 32-bit words (the
// lowest and highest symbol, the table's bytes, the data's bits, 0), the code lengths packed six
// bits each with runs of zeros shortened, then the codes, a run of up to 255 repeats of a value
// written as the value, a run pseudo-symbol and an 8-bit count where that is shorter.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace sdfreel {

// Appends the coding of raw[0..n) to `out`; returns the bytes appended (0 when n is 0).
size_t exr_huffman_compress(const uint16_t* raw, size_t n, std::vector<char>& out);

}  // namespace sdfreel
