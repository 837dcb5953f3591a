// The lenslets' optics: the twin of src/scenes/lenticular_card/optics.cpp.
#include "common/det_math.glsl"

float refracted_tan(float sin_theta, float ior) {
  precise float s = sin_theta / ior;
  precise float r = s / sqrt(1.0 - s * s);
  return r;
}

float seen_print_position(float centre, float sin_theta, float ior, float thickness) {
  precise float r = centre - thickness * refracted_tan(sin_theta, ior);
  return r;
}
