#pragma once
// The zlib stream that zlib itself writes for deflateInit2(level 1, Z_DEFLATED, window_bits,
// memLevel 8, Z_HUFFMAN_ONLY) fed `data` and finished, byte for byte: a two-byte header, blocks of
// 16383 literals (zlib's symbol buffer at memLevel 8) and a last block of the rest (empty when
// the rest is nothing), each coded with zlib's own trees (io/deflate_trees.h), then the Adler-32.
// The frame PNGs use this coding (io/png_frames.h); zlib's loop took 11 ns a byte, this under 3.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace sdfreel {

std::vector<uint8_t> zlib_huffman_only(const uint8_t* data, size_t size, int window_bits);

}  // namespace sdfreel
