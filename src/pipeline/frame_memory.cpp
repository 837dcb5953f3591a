#include "pipeline/frame_memory.h"

#include <sys/resource.h>

#include <cstdio>
#include <fstream>

#include "pipeline/errors.h"

namespace sdfreel {
namespace {

void keep_smaller(std::optional<MemoryLimit>& limit, uint64_t bytes, const char* source) {
  if (!limit || bytes < limit->bytes) limit = MemoryLimit{bytes, source};
}

std::string gib(uint64_t bytes) {
  char s[32];
  std::snprintf(s, sizeof s, "%.1f GiB", double(bytes) / double(1ull << 30));
  return s;
}

}  // namespace

uint64_t frame_bytes_lower_bound(int width, int height) {
  // 16 (RGBA float) + 8 (RGBA half) + 6 (rgb48 display) + 6 (its PNG or video frame).
  return uint64_t(width) * uint64_t(height) * 36;
}

std::optional<MemoryLimit> memory_limit() {
  std::optional<MemoryLimit> limit;
  std::ifstream meminfo("/proc/meminfo");
  for (std::string key; meminfo >> key;) {
    uint64_t kib = 0;
    meminfo >> kib;
    meminfo.ignore(1 << 10, '\n');
    if (key == "MemAvailable:") keep_smaller(limit, kib * 1024, "MemAvailable");
  }
  std::ifstream cgroup("/sys/fs/cgroup/memory.max");  // cgroup v2: a number or "max"
  if (uint64_t max = 0; cgroup >> max) keep_smaller(limit, max, "the cgroup's memory.max");
  rlimit as{};
  if (getrlimit(RLIMIT_AS, &as) == 0 && as.rlim_cur != RLIM_INFINITY)
    keep_smaller(limit, uint64_t(as.rlim_cur), "ulimit -v");
  return limit;
}

void check_frame_memory(const Timeline& tl) {
  const uint64_t need = frame_bytes_lower_bound(tl.width, tl.height);
  const std::optional<MemoryLimit> have = memory_limit();
  if (!have || need <= have->bytes) return;
  throw UsageError("a " + std::to_string(tl.width) + "x" + std::to_string(tl.height) +
                   " frame needs at least " + gib(need) + " (its images alone), and this process " +
                   "may have " + gib(have->bytes) + " (" + have->source +
                   "): render a smaller --resolution or [video] resolution");
}

}  // namespace sdfreel
