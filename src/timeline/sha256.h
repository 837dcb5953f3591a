#pragma once
// SHA-256 (FIPS 180-4) of a byte string, for the timeline hash in manifests. Self-contained so
// that the timeline library needs no libav.
#include <string>
#include <string_view>

namespace sdfreel {

// Lowercase hex digest, 64 characters.
std::string sha256_hex(std::string_view bytes);

}  // namespace sdfreel
