#pragma once
// The low `bytes` bytes of v, least significant first: how EXR files store every number.
#include <cstdint>
#include <vector>

namespace sdfreel {

inline void store_le(char* at, uint64_t v, int bytes) {
  for (int i = 0; i < bytes; ++i) at[i] = char(v >> (8 * i));
}

inline void append_le(std::vector<char>& out, uint64_t v, int bytes) {
  for (int i = 0; i < bytes; ++i) out.push_back(char(v >> (8 * i)));
}

}  // namespace sdfreel
