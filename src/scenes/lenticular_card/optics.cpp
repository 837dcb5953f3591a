#include "scenes/lenticular_card/optics.h"

#include <cmath>

#include "sdf/det_math.h"

namespace sdfreel::lenticular_card {

float refracted_tan(float sin_theta, float ior) {
  const float s = sin_theta / ior;
  return s / dm::sqrt(1.0f - s * s);
}

float seen_print_position(float centre, float sin_theta, float ior, float thickness) {
  return centre - thickness * refracted_tan(sin_theta, ior);
}

int seen_view(float sin_theta, float ior, float thickness, int views) {
  const float x = seen_print_position(0.5f, sin_theta, ior, thickness);
  const int strip = int(dm::mod(dm::floor(x * float(views)), float(views)));
  return views - 1 - strip;
}

double switch_angle_deg(int boundary, int views, double ior, double thickness) {
  // (0.5 - thickness * tan') * views = views / 2 - boundary  <=>  tan' = boundary / (views * e)
  const double t = double(boundary) / (double(views) * thickness);
  const double s = ior * t / std::sqrt(1.0 + t * t);
  return std::asin(s) * 180.0 / 3.14159265358979323846;
}

double scroll_offset(double time, double period, double hold) {
  const double cycles = time / period;
  const double k = std::floor(cycles);
  const double phase = cycles - k;
  const double x = std::min(std::max((phase - hold) / (1.0 - hold), 0.0), 1.0);
  const double slide = x * x * (3.0 - 2.0 * x);
  return std::fmod(std::fmod(k, 2.0) + slide, 2.0);
}

}  // namespace sdfreel::lenticular_card
