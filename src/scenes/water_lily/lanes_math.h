#pragma once
// det_math functions the water_lily geometry needs in eight lanes beyond sdf/lanes.h: mod here,
// atan2 from sdf/lanes_exp_log.h, with the scalar operations of sdf/det_math.h in the same order,
// so every lane gets the scalar bits (tests/scenes/water_lily/lanes_test.cpp).
#include "sdf/det_math.h"
#include "sdf/lanes.h"
#include "sdf/lanes_exp_log.h"

namespace sdfreel::dm {

inline F8 mod(F8 x, float y) {
  return x - y * floor(x / y);
}

}  // namespace sdfreel::dm
