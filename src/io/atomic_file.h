#pragma once
// Building blocks for atomic file writes: write to a temporary file in the destination's folder,
// then publish it with commit_temp_file (fsync, rename over the destination, fsync the folder).
// Every write, fsync, close and rename is checked: a short write (full disk) is never published.
#include <cstddef>
#include <string>

namespace sdfreel {

// A hidden temporary name beside `path`, unique per host, process and call:
// ".NAME.tmp-HOST-PID-N" (io/temp_name.h).
// It does not end in the destination's extension, so frame globs never pick it up.
std::string temp_path_for(const std::string& path);

// Writes all `size` bytes at the file offset; returns 0 or the errno of the failure (ENOSPC on a
// full disk, also when the file system accepts no more bytes without saying why).
int write_fully(int fd, const void* data, size_t size);
// fsync and close, each checked; returns 0 or the errno of the first failure (fd is closed).
int sync_and_close(int fd);

// Writes `bytes` to a fresh temporary beside `path`, checks the size on disk, then publishes it
// with commit_temp_file. Throws std::runtime_error naming `path`; leaves no temporary behind.
void write_file_atomic(const std::string& path, const void* data, size_t size);
inline void write_file_atomic(const std::string& path, const std::string& bytes) {
  write_file_atomic(path, bytes.data(), bytes.size());
}

// Flushes `temp` to disk and renames it to `path`. On failure removes `temp` and throws
// std::runtime_error.
void commit_temp_file(const std::string& temp, const std::string& path);

// Removes `temp` if it exists, ignoring errors (cleanup after a failed write).
void discard_temp_file(const std::string& temp) noexcept;

// Removes temporary files in `dir` left by killed writers of this host (their PID no longer runs
// here). Files of live processes (a concurrent shard) and of other hosts (shared storage: their
// PIDs cannot be checked from here) are left alone. Returns how many were removed.
int remove_stale_temp_files(const std::string& dir);

}  // namespace sdfreel
