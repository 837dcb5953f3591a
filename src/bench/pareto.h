#pragma once
// The speed-against-error front: configurations that no other one beats on both axes.
#include <cstddef>
#include <vector>

namespace sdfreel::bench {

struct SpeedError {
  double seconds;  // lower is better
  double psnr_db;  // higher is better
};

// on_front[i]: no point j is at least as fast and at least as accurate with one strictly better.
// Equal points are all on the front.
std::vector<bool> pareto_front(const std::vector<SpeedError>& points);

}  // namespace sdfreel::bench
