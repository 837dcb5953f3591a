#include "scenes/fur/spring.h"

#include <cmath>

namespace sdfreel::fur {

// 30 terms: x^30 / 30! < 1e-22 for |x| < 2.
double series_exp(double x) {
  double sum = 1.0, term = 1.0;
  for (int n = 1; n < 30; ++n) {
    term *= x / n;
    sum += term;
  }
  return sum;
}

double series_cos(double x) {
  double sum = 1.0, term = 1.0;
  for (int n = 1; n < 15; ++n) {
    term *= -x * x / ((2 * n - 1) * (2 * n));
    sum += term;
  }
  return sum;
}

double series_sin(double x) {
  double sum = x, term = x;
  for (int n = 1; n < 15; ++n) {
    term *= -x * x / ((2 * n) * (2 * n + 1));
    sum += term;
  }
  return sum;
}

SpringCoefficients spring_coefficients(double omega, double zeta, double dt) {
  SpringCoefficients c;
  c.omega = omega;
  c.zeta = zeta;
  c.dt = dt;
  const double wd = omega * std::sqrt(1.0 - zeta * zeta);  // sqrt is correctly rounded (IEEE)
  c.decay = series_exp(-zeta * omega * dt);
  c.cos_wd = series_cos(wd * dt);
  c.sin_wd_over_wd = series_sin(wd * dt) / wd;
  c.wd = wd;
  return c;
}

}  // namespace sdfreel::fur
