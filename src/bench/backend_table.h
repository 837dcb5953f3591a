#pragma once
// Two backends side by side per scene, from one bench run: seconds per frame of each at the same
// preset, their ratio, and each one's PSNR against the reference. CPU against llvmpipe
// (docs/performance.md, "CPU against llvmpipe") carries the target: the CPU at most half
// the time at equal or lower error. EGL against OSMesa (both llvmpipe) should be equal within
// noise, at the same PSNR.
#include <string>
#include <vector>

#include "bench/bench_row.h"

namespace sdfreel::bench {

constexpr double CPU_SPEEDUP_TARGET = 2.0;

struct BackendComparison {
  std::string scene, preset;
  std::string base, other;  // backend names, e.g. cpu and osmesa
  double base_seconds = 0.0, other_seconds = 0.0;
  double base_psnr_db = 0.0, other_psnr_db = 0.0;
  double speedup() const { return other_seconds / base_seconds; }  // > 1: the base is faster
  bool meets_target() const {
    return speedup() >= CPU_SPEEDUP_TARGET && base_psnr_db >= other_psnr_db;
  }
};

// One comparison per scene and named preset that both backends ran, in row order.
std::vector<BackendComparison> compare_backends(const std::vector<BenchRow>& rows,
                                                const std::string& base, const std::string& other);
// Markdown table of the comparisons; with_target adds the CPU target's column.
std::string format_backend_table(const std::vector<BackendComparison>& cmp, bool with_target);

}  // namespace sdfreel::bench
