#pragma once
// SHA-256 of a byte string (FIPS 180-4, written here: sdfreel links no libav library), for the
// timeline hash in manifests and the bench's reference cache. tests/io/digests_test.cpp holds it
// to FIPS's vectors and to libavutil's av_sha.
#include <string>
#include <string_view>

namespace sdfreel {

// Lowercase hex digest, 64 characters.
std::string sha256_hex(std::string_view bytes);

}  // namespace sdfreel
