#include "sdf/det_math.h"

#include <cmath>

namespace sdfreel::dm {

float wrap_phase(double x, double period) {
  if (!std::isfinite(x) || !(period > 0.0)) return 0.0f;
  // fmod is exact (no rounding), unlike x - period * floor(x / period).
  double r = std::fmod(x, period);
  if (r < 0.0) r += period;
  const float f = float(r);
  // Rounding to float (or the += above) can land exactly on period, which is the same phase as 0.
  return f >= float(period) ? 0.0f : f;
}

}  // namespace sdfreel::dm
