#pragma once
// Frame selections: `--frames 1,5,9-12` (inclusive ranges) and `--shard I/N`.
#include <string>
#include <vector>

namespace sdfreel {

// Sorted, unique frame indices; throws UsageError for syntax errors or frames >= count.
std::vector<int> parse_frame_list(const std::string& spec, int count);
// The I-th of N contiguous parts of `frames` (0-based), sizes differing by at most one.
// Throws UsageError unless 0 <= I < N.
std::vector<int> shard_of(const std::vector<int>& frames, const std::string& shard_spec);

}  // namespace sdfreel
