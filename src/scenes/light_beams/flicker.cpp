// The seed's flicker(seed, speed), with TIME's phases wrapped in double.
#include "scenes/light_beams/uniforms.h"

namespace sdfreel::light_beams {
namespace {

constexpr double PI_D = 3.141592653589793;
constexpr double TWO_PI_D = 6.283185307179586;

}  // namespace

float flicker_value(double seed, double speed, double scene_time) {
  const double s = seed / speed + scene_time;
  const float a = dm::sin(dm::wrap_phase(s / (0.1 * PI_D), TWO_PI_D));
  const float b = dm::cos(dm::wrap_phase(1.5 * s, TWO_PI_D));
  const float c = dm::cos(dm::wrap_phase(10.0 * s, TWO_PI_D));
  const float d = dm::sin(dm::wrap_phase(s / PI_D, TWO_PI_D) + c);
  return dm::cos(a + b) + d;
}

bool flicker(double seed, double speed, double scene_time) {
  return flicker_value(seed, speed, scene_time) > FLICKER_THRESHOLD;
}

}  // namespace sdfreel::light_beams
