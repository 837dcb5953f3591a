#pragma once
// The Huffman trees of zlib's deflate (its trees.c, unchanged from 1.2.11 to 1.3.1), step for
// step: the same heap, the same tie rule, the same fix for codes longer than 15 bits, the same
// run-length coding of the code lengths and the same choice between stored, fixed and dynamic
// blocks. A block coded here has zlib's bits, so io/huffman_deflate.h can replace zlib's
// Huffman-only loop without changing one byte of a frame file.
#include <cstddef>
#include <cstdint>

#include "io/bit_writer.h"

namespace sdfreel::deflate {

constexpr int LITERAL_CODES = 286, DISTANCE_CODES = 30, LENGTH_CODES = 19;
constexpr int END_OF_BLOCK = 256;

// A block's code of each symbol as BitWriter::put_each takes it: the code, bit-reversed for a
// writer that starts at the least significant bit, plus its length times 65536 (0: unused).
struct BlockCodes {
  uint32_t symbol[288];
};

// Codes one block of literals (a deflate block with no matches) as zlib's _tr_flush_block would:
// `counts` is how often each byte value occurs in `data`; `last` marks the stream's final block.
// The block's literals are then written with `codes` by the caller, so the hot
// loop stays outside; returns false when the block went out stored (its bytes already written).
bool start_block(BitWriter& out, const uint32_t counts[256], const uint8_t* data, size_t size,
                 bool last, BlockCodes& codes);

}  // namespace sdfreel::deflate
