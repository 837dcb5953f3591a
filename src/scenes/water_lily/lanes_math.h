#pragma once
// det_math functions the water_lily geometry needs in eight lanes beyond sdf/lanes.h: atan2 and
// mod, with the scalar operations of sdf/det_math.h in the same order (both sides of each branch,
// then a select), so every lane gets the scalar bits (tests/scenes/water_lily/lanes_test.cpp).
#include "sdf/det_math.h"
#include "sdf/lanes.h"

namespace sdfreel::dm {

inline F8 mod(F8 x, float y) {
  return x - y * floor(x / y);
}

inline F8 atan_unit(F8 t) {
  const M8 big = t > TAN_PI_8;
  const F8 base = select(big, splat(QUARTER_PI), splat(0.0f));
  t = select(big, (t - 1.0f) / (t + 1.0f), t);
  const F8 z = t * t;
  return base + ((((8.05374449538e-2f * z - 1.38776856032e-1f) * z + 1.99777106478e-1f) * z -
                  3.33329491539e-1f) *
                     z * t +
                 t);
}

inline F8 atan2(F8 y, F8 x) {
  const F8 ax = abs(x), ay = abs(y);
  const F8 hi = max(ax, ay), lo = min(ax, ay);
  F8 a = atan_unit(lo / hi);
  a = select(ay > ax, HALF_PI - a, a);
  a = select(x < 0.0f, PI - a, a);
  a = select(y < 0.0f, -a, a);
  return select(hi == 0.0f, splat(0.0f), a);
}

}  // namespace sdfreel::dm
