#pragma once
// `sdfreel bench --micro`: Google Benchmark micro-benchmarks of each scene's distance functions
// (Scene::distance_functions), scalar and eight lanes, as evaluations per second. Each function is
// first checked for identical bits in both paths at every sample point.
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "bench/micro_points.h"
#include "scenes/scene.h"

namespace sdfreel::bench {

// A prepared scene's functions and the points to evaluate them at. `owner` keeps the scene alive:
// the functions usually capture it.
struct MicroTarget {
  std::string scene;
  std::shared_ptr<const Scene> owner;
  std::vector<DistanceFunction> functions;
  SamplePoints points;
};

struct MicroOptions {
  int repetitions = 5;    // --benchmark_repetitions; the median is reported
  double min_time = 0.1;  // --benchmark_min_time, seconds per repetition
};

struct MicroRow {
  std::string scene, function;
  int points = 0;
  // Medians over repetitions; per second of the benchmark thread's CPU time (Google Benchmark's
  // rate counters), which load from other processes on a shared machine disturbs less.
  double scalar_evals_per_s = 0.0, lanes_evals_per_s = 0.0;
  double lanes_over_scalar() const { return lanes_evals_per_s / scalar_evals_per_s; }
};

// A function whose lanes give other bits than its scalar path (exit status 1 in the CLI).
struct LaneMismatchError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Throws LaneMismatchError for the first function whose paths differ (before any timing).
void check_lanes_match_scalar(const std::vector<MicroTarget>& targets);

// Checks, then registers "SCENE/FUNCTION/scalar" and "SCENE/FUNCTION/lanes" for every function
// (each iteration evaluates every point once) and runs them through Google Benchmark. One row per
// function, in the targets' order. Replaces any benchmarks registered before, and leaves none.
std::vector<MicroRow> run_micro_benchmarks(const std::vector<MicroTarget>& targets,
                                           const MicroOptions& options);

}  // namespace sdfreel::bench
