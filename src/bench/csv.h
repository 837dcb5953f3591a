#pragma once
// bench.csv: one row per scene, backend and configuration.
#include <functional>
#include <ostream>
#include <string>
#include <vector>

#include "bench/bench_row.h"

namespace sdfreel::bench {

std::vector<std::string> csv_columns();
void write_csv(std::ostream& out, const std::vector<BenchRow>& rows);
// Writes DIR/bench.csv atomically: every write checked, to a temporary name unique to this writer,
// then renamed (io/atomic_file.h). Throws std::runtime_error naming `path`.
void write_csv_file(const std::string& path, const std::vector<BenchRow>& rows);
// What write_csv_file does for any report: `write` fills a buffer, published by write_file_atomic.
void write_file_via_temp(const std::string& path, const std::function<void(std::ostream&)>& write);

// Splits one CSV line (no quoting: bench.csv has none) — for tests and tools.
std::vector<std::string> split_csv_line(const std::string& line);

}  // namespace sdfreel::bench
