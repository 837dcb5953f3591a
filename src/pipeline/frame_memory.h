#pragma once
// Memory for a frame, checked where a frame pipeline is made (and by check), before anything is
// written: a 16384x16384 render where the process may not have the memory ended in
// std::bad_alloc (exit 1) after it had started. Not at load time: `slurm` loads a timeline on the
// submit host, whose memory is not the nodes', and `sheet` renders tiles smaller than the
// timeline's size.
#include <cstdint>
#include <optional>
#include <string>

#include "timeline/timeline.h"

namespace sdfreel {

// What every render of a w x h frame keeps at once, whatever the scene: linear RGBA floats, their
// half copy, the 16-bit display image and its encoding. A lower bound: scenes need more.
uint64_t frame_bytes_lower_bound(int width, int height);

struct MemoryLimit {
  uint64_t bytes;
  std::string source;  // "MemAvailable", "the cgroup's memory.max", "ulimit -v"
};
// The least this process may allocate by the kernel's accounts; nothing when none is known.
std::optional<MemoryLimit> memory_limit();

// UsageError naming both sizes when the lower bound exceeds memory_limit().
void check_frame_memory(const Timeline& tl);

}  // namespace sdfreel
