#pragma once
// One measured configuration of one scene and backend: a line of bench.csv and of the table.
#include <string>

#include "render/quality.h"

namespace sdfreel::bench {

struct BenchRow {
  std::string scene, backend, preset;  // preset: naive, draft, final, or a sweep point's name
  bool named_preset = false;           // naive/draft/final (labelled in the plot)
  MarchSettings march{};
  int samples = 1;
  double mean_samples = 1.0;  // samples a pixel took on average (adaptive sampling varies them)
  double seconds_per_frame = 0.0;  // median over repetitions
  double psnr_db = 0.0, rmse = 0.0, mean_abs_error = 0.0, p99_abs_error = 0.0;
  double hitmiss_fraction = 0.0;
  double sdf_evals_per_pixel = 0.0;
  double capped_per_pixel = 0.0;  // rays that ran out of steps, per pixel (CPU backend only)
  bool on_front = false;          // Pareto front of its scene and backend
};

}  // namespace sdfreel::bench
