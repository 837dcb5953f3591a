#pragma once
// A display value clamped to [0,1] and rounded to 16 bits: the unit of the PNG frames and of the
// framemd5. NaN maps to 0, so that a bad pixel can never become an out-of-range integer conversion.
#include <cstdint>

namespace sdfreel {

inline uint16_t quantise16(float v) {
  if (!(v > 0.0f)) return 0;
  if (v >= 1.0f) return 65535;
  // lround(x) for x = v * 65535 in (0, 65535), without its libm call (a tenth of the display
  // transform's time): x + 0.5 is exact in double whenever it could reach the next integer, so
  // truncating it rounds half away from zero as lround does (tests/io/half_rounding_test.cpp).
  return static_cast<uint16_t>(double(v * 65535.0f) + 0.5);
}

}  // namespace sdfreel
