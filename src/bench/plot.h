#pragma once
// The speed-against-error plot of one scene: seconds per frame on a log x axis against PSNR, one
// colour per backend, the Pareto front of each backend ringed and joined, presets labelled.
#include <string>
#include <vector>

#include "bench/bench_row.h"

namespace sdfreel::bench {

// rows: one scene's rows (every backend). Throws std::runtime_error when the file cannot be
// written.
void plot_speed_error(const std::vector<BenchRow>& rows, const std::string& title,
                      const std::string& path);

}  // namespace sdfreel::bench
