#pragma once
// The micro-benchmark's table for stdout (Markdown, like the bench table) and micro.csv.
#include <ostream>
#include <string>
#include <vector>

#include "bench/micro_bench.h"

namespace sdfreel::bench {

std::string format_micro_table(const std::vector<MicroRow>& rows);
// Columns: scene,function,points,scalar_evals_per_s,lanes_evals_per_s,lanes_over_scalar.
void write_micro_csv(std::ostream& out, const std::vector<MicroRow>& rows);
// To a temporary name, then renamed.
void write_micro_csv_file(const std::string& path, const std::vector<MicroRow>& rows);

}  // namespace sdfreel::bench
