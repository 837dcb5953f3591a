#pragma once
// Building blocks for atomic file writes: write to a temporary file in the destination's folder,
// then publish it with commit_temp_file (fsync, rename over the destination, fsync the folder).
#include <string>

namespace sdfreel {

// A hidden temporary name beside `path`, unique per process and call: ".NAME.tmp-PID-N".
// It does not end in the destination's extension, so frame globs never pick it up.
std::string temp_path_for(const std::string& path);

// Flushes `temp` to disk and renames it to `path`. On failure removes `temp` and throws
// std::runtime_error.
void commit_temp_file(const std::string& temp, const std::string& path);

// Removes `temp` if it exists, ignoring errors (cleanup after a failed write).
void discard_temp_file(const std::string& temp) noexcept;

// Removes temporary files in `dir` left by killed writers (their PID no longer runs). Files of
// live processes (a concurrent shard) are left alone. Returns how many were removed.
int remove_stale_temp_files(const std::string& dir);

}  // namespace sdfreel
