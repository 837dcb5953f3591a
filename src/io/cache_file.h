#pragma once
// Files in the cache folder (cache_dir()) that can always be made again. Each holds its full key
// (the caller's key plus build_id()) and a checksum; a file whose key or checksum does not match
// (torn, truncated, corrupt, another build's) reads as missing, so its content is made again and
// never trusted. Writes are atomic (write_file_atomic) and best effort: a read-only or full cache
// folder only costs the time to make the content again.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace sdfreel {

// cache_dir()/<kind>/<hash of key>-<hash of build_id()>.bin, or empty when there is no cache
// folder. Writing a key's file removes that key's files of other builds.
std::filesystem::path cache_file_path(const std::string& kind, const std::string& key);

std::optional<std::vector<char>> read_cache_file(const std::string& kind, const std::string& key);
// Returns false (and leaves nothing behind) when the file could not be written.
bool write_cache_file(const std::string& kind, const std::string& key,
                      const std::vector<char>& payload);

// 64-bit checksum of a byte range (four interleaved multiply-xorshift lanes: about 1 ms per 8 MB).
uint64_t checksum64(const void* data, size_t size);

}  // namespace sdfreel
