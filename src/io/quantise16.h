#pragma once
// A display value clamped to [0,1] and rounded to 16 bits: the unit of the PNG frames and of the
// framemd5. NaN maps to 0, so that a bad pixel can never become an out-of-range integer conversion.
#include <cmath>
#include <cstdint>

namespace sdfreel {

inline uint16_t quantise16(float v) {
  if (!(v > 0.0f)) return 0;
  if (v >= 1.0f) return 65535;
  return static_cast<uint16_t>(std::lround(v * 65535.0f));
}

}  // namespace sdfreel
