#pragma once
// SHA-256 of a byte string (libavutil's), for the timeline hash in manifests and the bench's
// reference cache.
#include <string>
#include <string_view>

namespace sdfreel {

// Lowercase hex digest, 64 characters.
std::string sha256_hex(std::string_view bytes);

}  // namespace sdfreel
