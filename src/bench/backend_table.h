#pragma once
// The CPU backend against llvmpipe (OSMesa) per scene, from one bench run: seconds per frame of
// each at the same preset, their ratio, and each one's PSNR against the reference (README "CPU
// against llvmpipe"). The issue's target: the CPU at most half the time at equal or lower error.
#include <string>
#include <vector>

#include "bench/bench_row.h"

namespace sdfreel::bench {

constexpr double CPU_SPEEDUP_TARGET = 2.0;

struct BackendComparison {
  std::string scene, preset;
  double cpu_seconds = 0.0, osmesa_seconds = 0.0;
  double cpu_psnr_db = 0.0, osmesa_psnr_db = 0.0;
  double speedup() const { return osmesa_seconds / cpu_seconds; }  // > 1: the CPU is faster
  bool meets_target() const {
    return speedup() >= CPU_SPEEDUP_TARGET && cpu_psnr_db >= osmesa_psnr_db;
  }
};

// One comparison per scene and named preset that both backends ran, in row order.
std::vector<BackendComparison> compare_backends(const std::vector<BenchRow>& rows);
// Markdown table of the comparisons.
std::string format_backend_table(const std::vector<BackendComparison>& cmp);

}  // namespace sdfreel::bench
