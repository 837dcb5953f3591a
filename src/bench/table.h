#pragma once
// The bench's table for stdout and README.md (a Markdown table).
#include <string>
#include <vector>

#include "bench/bench_row.h"

namespace sdfreel::bench {

// all = false: only the named presets (naive, draft, final) and the points on the front.
std::string format_table(const std::vector<BenchRow>& rows, bool all);

}  // namespace sdfreel::bench
