#pragma once
// `sdfreel bench --whole-process`: each target rendered end to end as a user runs it, a fresh
// `sdfreel render TIMELINE --frames F --no-video --backend B` (frames and hashes written), on each
// backend, the backends alternating within each repetition so that load from elsewhere lands on
// all of them; medians. The table gives each backend's time against the CPU's: the ratio the
// docs/performance.md's "CPU against llvmpipe" table quotes, in one command.
#include <string>
#include <vector>

#include "bench/process_time.h"

namespace sdfreel::bench {

struct WholeProcessRow {
  std::string scene, backend;
  int frames = 0, width = 0, height = 0;
  std::string samples;  // "4", or "adaptive 1..16"
  ProcessTime time;     // medians of wall and CPU seconds
};

// The render's arguments after the executable: `render TIMELINE --frames F --no-video --backend B
// --out OUT`, with `--resolution R` when `resolution` is not empty.
std::vector<std::string> whole_process_args(const std::string& timeline, const std::string& frames,
                                            const std::string& resolution,
                                            const std::string& backend, const std::string& out);

// Markdown: one row per scene and backend, seconds (wall, per frame, CPU) and, for every backend
// but the CPU, how many times longer it took than the CPU on the same scene ("cpu" measured).
std::string format_whole_process_table(const std::vector<WholeProcessRow>& rows);

// CSV with a header line.
std::string whole_process_csv(const std::vector<WholeProcessRow>& rows);

}  // namespace sdfreel::bench
