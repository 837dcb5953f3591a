#pragma once
// Reading a small input file without trusting it: only regular files (a FIFO would block forever,
// /dev/zero never ends), and never more than a cap.
#include <cstdint>
#include <optional>
#include <string>

namespace sdfreel {

// 256 MiB: a manifest of about 800,000 frames (over 3 hours at 60 fps).
constexpr uint64_t kMaxManifestBytes = uint64_t(256) << 20;

// The bytes of `path`; nullopt when it does not exist. Throws std::runtime_error when it is not a
// regular file, is larger than `max_bytes`, or cannot be read.
std::optional<std::string> read_regular_file(const std::string& path, uint64_t max_bytes);
// The same refusals without reading the bytes (a missing file too). Throws std::runtime_error.
void check_regular_file(const std::string& path, uint64_t max_bytes);

}  // namespace sdfreel
