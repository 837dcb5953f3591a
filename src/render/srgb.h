#pragma once
// The sRGB curve's decoding (IEC 61966-2-1 EOTF), with the project's deterministic pow, so that
// the same numbers give the same bits whatever libm the build runs on.
#include "sdf/det_math.h"

namespace sdfreel {

// Display value -> linear: c / 12.92 up to 0.04045, ((c + 0.055) / 1.055)^2.4 above (values
// above 1, from HDR shaders, extend the curve). Values at or below 0 (NaN too) give 0.
inline float srgb_to_linear(float c) {
  if (!(c > 0.0f)) return 0.0f;
  return c <= 0.04045f ? c / 12.92f : dm::pow((c + 0.055f) / 1.055f, 2.4f);
}

}  // namespace sdfreel
