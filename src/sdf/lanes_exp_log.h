#pragma once
// exp, log, pow, atan2, asin, acos of det_math.h on eight lanes: each lane performs the scalar
// function's operations in its order, both sides of every branch computed and one selected, so a
// lane has the scalar's bits for every input, NaN, infinities and denormals included
// (tests/sdf/lanes_exp_log_test.cpp). The display transform runs on them (io/aces_sdr_video.cpp),
// water_lily's lanes use atan2, light_beams' atan2 and asin, lantern_festival's sky atan2 and
// acos.
#include <cfloat>
#include <cstdint>

#include "sdf/det_math.h"
#include "sdf/lanes.h"

namespace sdfreel {

typedef uint32_t U8 __attribute__((vector_size(32)));

namespace dm {

// exp2_int on lanes, and int(x) (truncating) and float(k) under one name for floats and lanes, so
// one template serves both.
inline F8 exp2_int(M8 k) {
  return reinterpret_cast<F8>(reinterpret_cast<U8>(k + 127) << 23);
}
inline int to_int(float x) {
  return int(x);
}
inline float to_float(int k) {
  return float(k);
}
inline M8 to_int(F8 x) {
  return __builtin_convertvector(x, M8);
}
inline F8 to_float(M8 k) {
  return __builtin_convertvector(k, F8);
}

inline F8 exp(F8 x) {
  const M8 underflow = x < EXP_MIN_ARG;
  // The scalar returns before converting such an x to int; here it is converted, so in range.
  x = min(max(x, EXP_MIN_ARG), EXP_MAX_ARG);
  const F8 k = floor(x * LOG2E + 0.5f);
  F8 r = x - k * LN2_HI;
  r = r - k * LN2_LO;
  const F8 p = exp_polynomial(r);
  const F8 k1 = floor(k * 0.5f);
  const F8 v = p * exp2_int(to_int(k1)) * exp2_int(to_int(k - k1));
  return select(underflow, splat(0.0f), v);
}

inline F8 log(F8 x) {
  const M8 not_positive = ~(x > 0.0f);  // NaN included
  x = min(x, FLT_MAX);
  const M8 denormal = x < FLT_MIN;
  x = select(denormal, x * TWO_POW_23, x);
  M8 e = denormal & -23;
  const U8 bits = reinterpret_cast<U8>(x);
  e = e + (reinterpret_cast<M8>((bits >> 23) & 0xffu) - 126);
  F8 m = reinterpret_cast<F8>((bits & 0x007fffffu) | 0x3f000000u);
  const M8 below = m < SQRT_HALF;
  e = e + below;  // -1 where below
  m = select(below, m + m - 1.0f, m - 1.0f);
  return select(not_positive, splat(LOG_OF_ZERO), log_of_reduced(m, to_float(e)));
}

// pow with a uniform exponent, the case of every caller.
inline F8 pow(F8 x, float y) {
  const float at_zero = y > 0.0f ? 0.0f : (y == 0.0f ? 1.0f : POW_ZERO_NEGATIVE);
  return select(x <= 0.0f, splat(at_zero), exp(y * log(x)));
}

inline F8 atan_unit(F8 t) {
  const M8 above = t > TAN_PI_8;
  const F8 base = select(above, splat(QUARTER_PI), splat(0.0f));
  t = select(above, (t - 1.0f) / (t + 1.0f), t);
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

inline F8 asin(F8 x) {
  x = clamp(x, -1.0f, 1.0f);
  const F8 a = abs(x);
  const F8 r =
      select(a > 0.5f, HALF_PI - 2.0f * asin_kernel(sqrt(0.5f * (1.0f - a))), asin_kernel(a));
  return select(x < 0.0f, -r, r);
}

inline F8 acos(F8 x) {
  x = clamp(x, -1.0f, 1.0f);
  const F8 below = PI - 2.0f * asin_kernel(sqrt(0.5f * (1.0f + x)));
  const F8 above = 2.0f * asin_kernel(sqrt(0.5f * (1.0f - x)));
  const F8 middle = HALF_PI - asin_kernel(abs(x)) * sign(x);
  return select(x < -0.5f, below, select(x > 0.5f, above, middle));
}

}  // namespace dm
}  // namespace sdfreel
