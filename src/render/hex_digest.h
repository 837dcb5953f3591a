#pragma once
// A digest's bytes as lowercase hex, two characters a byte: how the frame hashes (io/md5.h) and
// the timeline's SHA-256 (timeline/sha256.h) are printed.
#include <cstddef>
#include <cstdint>
#include <string>

namespace sdfreel {

inline std::string hex_digest(const uint8_t* bytes, size_t n) {
  static const char DIGITS[] = "0123456789abcdef";
  std::string out(n * 2, '0');
  for (size_t i = 0; i < n; ++i) {
    out[2 * i] = DIGITS[bytes[i] >> 4];
    out[2 * i + 1] = DIGITS[bytes[i] & 15];
  }
  return out;
}

}  // namespace sdfreel
