#pragma once
// Times of one call: process CPU time (all threads; on a loaded shared machine the honest measure
// of work when the methods run on one thread) and wall time.
#include <functional>
#include <vector>

namespace sdfreel::mesh_bench {

struct Elapsed {
  double cpu_ms, wall_ms;
};

Elapsed time_call(const std::function<void()>& fn);
double median(std::vector<double> v);

}  // namespace sdfreel::mesh_bench
