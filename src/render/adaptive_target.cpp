#include "render/adaptive_target.h"

#include <algorithm>
#include <cmath>

namespace sdfreel {

float threshold_for_target_db(double db) {
  const double mse = std::pow(10.0, -db / 10.0);
  return float(std::max(0.0, (mse - ADAPTIVE_MSE_FLOOR) / ADAPTIVE_MSE_PER_THRESHOLD));
}

}  // namespace sdfreel
