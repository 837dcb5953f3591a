#include "bench/pareto.h"

namespace sdfreel::bench {

std::vector<bool> pareto_front(const std::vector<SpeedError>& points) {
  std::vector<bool> on_front(points.size(), true);
  for (size_t i = 0; i < points.size(); ++i)
    for (size_t j = 0; j < points.size() && on_front[i]; ++j) {
      const SpeedError& a = points[i];
      const SpeedError& b = points[j];
      const bool no_worse = b.seconds <= a.seconds && b.psnr_db >= a.psnr_db;
      const bool better = b.seconds < a.seconds || b.psnr_db > a.psnr_db;
      if (no_worse && better) on_front[i] = false;
    }
  return on_front;
}

}  // namespace sdfreel::bench
