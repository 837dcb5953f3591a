#pragma once
// Deterministic float math for every render path, in place of libm.
//
// Each function uses only +, -, *, /, floor, sqrt (all exact IEEE operations) and bit
// reinterpretation, in a fixed order of evaluation. Built with -ffp-contract=off and no fast-math,
// the results are the same bits with any compiler on any x86-64 machine, and every function is
// short enough to be written out line for line in GLSL (shaders/common) for the OSMesa backend. The
// polynomials are the Cephes single-precision minimax fits (Moshier), reduced with Cody-Waite
// constants.
//
// Domains and measured accuracy (tests/sdf/det_math_test.cpp checks these against libm):
//   sin, cos    |x| <= 1e5, absolute error < 2e-7 (finite, bounded result for any finite x)
//   atan2       any finite y, x; atan2(0, 0) = 0; -0 is treated as +0; abs error < 3e-7
//   asin, acos  input clamped to [-1, 1]; abs error < 4e-7
//   exp         relative error < 3e-7; 0 below ln(FLT_MIN), FLT_MAX-ish cap above 88.72
//   log         relative error < 3e-7 (absolute < 1e-7 near 1); log(x <= 0) = -FLT_MAX
//   pow         exp(y * log(x)): relative error < 1.5e-7 * (1 + |y ln x|), so < 1e-5 while
//               |y ln x| < 60; pow(0, y>0) = 0, pow(0, 0) = 1, pow(0, y<0) = FLT_MAX;
//               a negative base counts as 0 (like pow(max(x, 0), y), the usual shader intent)
//   tanh        absolute error < 3e-7
// No function returns NaN for a finite argument in its domain, or Inf at all.
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <glm/glm.hpp>

namespace sdfreel::dm {

constexpr float PI = 3.14159265358979f;
constexpr float TWO_PI = 6.28318530717959f;
constexpr float HALF_PI = 1.57079632679490f;
constexpr float QUARTER_PI = 0.785398163397448f;

// ---- GLSL built-ins with exact semantics (IEEE-exact operations only) ----

inline float floor(float x) {
  return std::floor(x);
}
inline float sqrt(float x) {
  return std::sqrt(x);
}
inline float abs(float x) {
  return std::fabs(x);
}
inline float min(float a, float b) {
  return b < a ? b : a;
}
inline float max(float a, float b) {
  return a < b ? b : a;
}
inline float clamp(float x, float lo, float hi) {
  return min(max(x, lo), hi);
}
// GLSL: x - floor(x). Like GLSL it may return 1.0 for tiny negative x (rounding of 1 - tiny).
inline float fract(float x) {
  return x - std::floor(x);
}
// GLSL: x - y * floor(x / y).
inline float mod(float x, float y) {
  return x - y * std::floor(x / y);
}
// GLSL spec form x * (1 - a) + y * a: exact at a = 0 and a = 1.
inline float mix(float x, float y, float a) {
  return x * (1.0f - a) + y * a;
}
inline float step(float edge, float x) {
  return x < edge ? 0.0f : 1.0f;
}
// GLSL smoothstep; e0 == e1 (undefined in GLSL) is a step at e0 here instead of a division by 0.
inline float smoothstep(float e0, float e1, float x) {
  if (e0 == e1) return x < e0 ? 0.0f : 1.0f;
  const float t = clamp((x - e0) / (e1 - e0), 0.0f, 1.0f);
  return t * t * (3.0f - 2.0f * t);
}
inline float sign(float x) {
  return x > 0.0f ? 1.0f : (x < 0.0f ? -1.0f : 0.0f);
}

inline glm::vec3 mix(const glm::vec3& x, const glm::vec3& y, float a) {
  return x * (1.0f - a) + y * a;
}
inline glm::vec2 mix(const glm::vec2& x, const glm::vec2& y, float a) {
  return x * (1.0f - a) + y * a;
}
inline glm::vec3 clamp(const glm::vec3& v, float lo, float hi) {
  return glm::vec3(clamp(v.x, lo, hi), clamp(v.y, lo, hi), clamp(v.z, lo, hi));
}

// GLSL floatBitsToUint / uintBitsToFloat.
inline uint32_t float_bits(float x) {
  uint32_t u;
  std::memcpy(&u, &x, sizeof u);
  return u;
}
inline float bits_float(uint32_t u) {
  float x;
  std::memcpy(&x, &u, sizeof x);
  return x;
}

// ---- sin, cos ----

// pi/2 as four floats whose first three have at most 8 significant bits: k * C is exact for
// |k| < 2^16, i.e. |x| up to about 1.02e5, so the reduction loses nothing there.
constexpr float PIO2_1 = 1.5703125f;
constexpr float PIO2_2 = 4.825592041015625e-4f;
constexpr float PIO2_3 = 1.2665987014770508e-6f;
constexpr float PIO2_4 = 9.920936294705029e-10f;
constexpr float TWO_OVER_PI = 0.636619772367581f;
// Reduced arguments never exceed pi/4 + 0.01 in the domain; the clamp only keeps out-of-domain
// inputs finite.
constexpr float REDUCED_LIMIT = 1.0f;

// x = k * pi/2 + r with |r| <= ~pi/4; quadrant = k mod 4 in 0..3.
struct QuadrantReduced {
  float r;
  int quadrant;
};

inline QuadrantReduced reduce_half_pi(float x) {
  const float k = std::floor(x * TWO_OVER_PI + 0.5f);
  float r = x - k * PIO2_1;
  r = r - k * PIO2_2;
  r = r - k * PIO2_3;
  r = r - k * PIO2_4;
  r = clamp(r, -REDUCED_LIMIT, REDUCED_LIMIT);
  // k mod 4 computed in float: exact for every float k (large floats are multiples of 4).
  const float q = k - 4.0f * std::floor(k * 0.25f);
  return {r, int(q)};
}

// Kernels on |r| <= pi/4.
inline float sin_kernel(float r) {
  const float z = r * r;
  return ((-1.9515295891e-4f * z + 8.3321608736e-3f) * z - 1.6666654611e-1f) * z * r + r;
}
inline float cos_kernel(float r) {
  const float z = r * r;
  float y =
      ((2.443315711809948e-5f * z - 1.388731625493765e-3f) * z + 4.166664568298827e-2f) * z * z;
  y = y - 0.5f * z;
  return y + 1.0f;
}

inline float sin(float x) {
  const QuadrantReduced a = reduce_half_pi(x);
  switch (a.quadrant) {
    case 0:
      return sin_kernel(a.r);
    case 1:
      return cos_kernel(a.r);
    case 2:
      return -sin_kernel(a.r);
    default:
      return -cos_kernel(a.r);
  }
}

inline float cos(float x) {
  const QuadrantReduced a = reduce_half_pi(x);
  switch (a.quadrant) {
    case 0:
      return cos_kernel(a.r);
    case 1:
      return -sin_kernel(a.r);
    case 2:
      return -cos_kernel(a.r);
    default:
      return sin_kernel(a.r);
  }
}

// ---- atan, atan2, asin, acos ----

constexpr float TAN_PI_8 = 0.414213562373095f;

// atan(t) for t in [0, 1].
inline float atan_unit(float t) {
  float base = 0.0f;
  if (t > TAN_PI_8) {
    base = QUARTER_PI;
    t = (t - 1.0f) / (t + 1.0f);
  }
  const float z = t * t;
  return base + ((((8.05374449538e-2f * z - 1.38776856032e-1f) * z + 1.99777106478e-1f) * z -
                  3.33329491539e-1f) *
                     z * t +
                 t);
}

inline float atan(float x) {
  const float a = abs(x);
  const float r = a > 1.0f ? HALF_PI - atan_unit(1.0f / a) : atan_unit(a);
  return x < 0.0f ? -r : r;
}

// GLSL atan(y, x), with atan2(0, 0) = 0 and -0 treated as +0.
inline float atan2(float y, float x) {
  const float ax = abs(x), ay = abs(y);
  const float hi = max(ax, ay), lo = min(ax, ay);
  if (hi == 0.0f) return 0.0f;
  float a = atan_unit(lo / hi);
  if (ay > ax) a = HALF_PI - a;
  if (x < 0.0f) a = PI - a;
  return y < 0.0f ? -a : a;
}

// asin(s) for s in [0, 0.5]; a template so that lanes (sdf/lanes.h's F8) run the same operations.
template <class F>
inline F asin_kernel(F s) {
  const F z = s * s;
  return ((((4.2163199048e-2f * z + 2.4181311049e-2f) * z + 4.5470025998e-2f) * z +
           7.4953002686e-2f) *
              z +
          1.6666752422e-1f) *
             z * s +
         s;
}

inline float asin(float x) {
  x = clamp(x, -1.0f, 1.0f);
  const float a = abs(x);
  // Near |x| = 1 use asin(a) = pi/2 - 2 asin(sqrt((1 - a) / 2)), which keeps the kernel in [0,
  // 0.5].
  const float r = a > 0.5f ? HALF_PI - 2.0f * asin_kernel(sqrt(0.5f * (1.0f - a))) : asin_kernel(a);
  return x < 0.0f ? -r : r;
}

inline float acos(float x) {
  x = clamp(x, -1.0f, 1.0f);
  if (x < -0.5f) return PI - 2.0f * asin_kernel(sqrt(0.5f * (1.0f + x)));
  if (x > 0.5f) return 2.0f * asin_kernel(sqrt(0.5f * (1.0f - x)));
  return HALF_PI - asin_kernel(abs(x)) * sign(x);
}

// ---- exp, log, pow, tanh ----

constexpr float LOG2E = 1.44269504088896f;
constexpr float LN2_HI = 0.693359375f;       // 9 significant bits: k * LN2_HI exact for |k| <= 2^15
constexpr float LN2_LO = -2.12194440e-4f;    // LN2_HI + LN2_LO = ln 2
constexpr float EXP_MIN_ARG = -87.3365448f;  // ln(FLT_MIN): below it the result would be denormal
constexpr float EXP_MAX_ARG = 88.7228f;      // just under ln(FLT_MAX)
constexpr float SQRT_HALF = 0.707106781186548f;
constexpr float LOG_OF_ZERO = -FLT_MAX;       // stands in for -Inf: exp(LOG_OF_ZERO) = 0
constexpr float POW_ZERO_NEGATIVE = FLT_MAX;  // stands in for +Inf (0 to a negative power)

// exp's minimax polynomial on the reduced argument r, and log's value from the reduced mantissa
// m - 1 and the exponent e (as a float): one template for the scalar functions and their lanes
// (sdf/lanes_exp_log.h).
template <class T>
inline T exp_polynomial(T r) {
  const T z = r * r;
  return (((((1.9875691500e-4f * r + 1.3981999507e-3f) * r + 8.3334519073e-3f) * r +
            4.1665795894e-2f) *
               r +
           1.6666665459e-1f) *
              r +
          5.0000001201e-1f) *
             z +
         r + 1.0f;
}
template <class T>
inline T log_of_reduced(T m, T fe) {
  const T z = m * m;
  T y = ((((((((7.0376836292e-2f * m - 1.1514610310e-1f) * m + 1.1676998740e-1f) * m -
              1.2420140846e-1f) *
                 m +
             1.4249322787e-1f) *
                m -
            1.6668057665e-1f) *
               m +
           2.0000714765e-1f) *
              m -
          2.4999993993e-1f) *
             m +
         3.3333331174e-1f) *
        m * z;
  y = y + LN2_LO * fe;
  y = y - 0.5f * z;
  T r = m + y;
  r = r + LN2_HI * fe;
  return r;
}

// 2^k for integer k in [-126, 127], built from the exponent bits.
inline float exp2_int(int k) {
  return bits_float(uint32_t(k + 127) << 23);
}

inline float exp(float x) {
  if (x < EXP_MIN_ARG) return 0.0f;
  x = min(x, EXP_MAX_ARG);
  const float k = std::floor(x * LOG2E + 0.5f);  // in [-126, 128]
  float r = x - k * LN2_HI;
  r = r - k * LN2_LO;
  const float p = exp_polynomial(r);
  // 2^k in two factors so that k = 128 and k = -126 stay within normal exponents.
  const float k1 = std::floor(k * 0.5f);
  return p * exp2_int(int(k1)) * exp2_int(int(k - k1));
}

constexpr float TWO_POW_23 = 8388608.0f;

inline float log(float x) {
  if (!(x > 0.0f)) return LOG_OF_ZERO;  // also catches NaN
  x = min(x, FLT_MAX);                  // +Inf -> log(FLT_MAX)
  int e = 0;
  if (x < FLT_MIN) {  // denormal: scale into the normal range first
    x = x * TWO_POW_23;
    e = -23;
  }
  const uint32_t bits = float_bits(x);
  e += int((bits >> 23) & 0xffu) - 126;
  float m = bits_float((bits & 0x007fffffu) | 0x3f000000u);  // mantissa in [0.5, 1)
  if (m < SQRT_HALF) {
    e -= 1;
    m = m + m - 1.0f;
  } else {
    m = m - 1.0f;
  }
  return log_of_reduced(m, float(e));
}

inline float pow(float x, float y) {
  if (x <= 0.0f) {
    if (y > 0.0f) return 0.0f;
    return y == 0.0f ? 1.0f : POW_ZERO_NEGATIVE;
  }
  return exp(y * log(x));
}

constexpr float TANH_POLY_LIMIT = 0.625f;

inline float tanh(float x) {
  const float a = abs(x);
  float r;
  if (a > TANH_POLY_LIMIT) {
    r = 1.0f - 2.0f / (exp(a + a) + 1.0f);
  } else {
    const float z = x * x;
    r = ((((-5.70498872745e-3f * z + 2.06390887954e-2f) * z - 5.37397155531e-2f) * z +
          1.33314422036e-1f) *
             z -
         3.33332819422e-1f) *
            z * a +
        a;
  }
  return x < 0.0f ? -r : r;
}

// ---- time phases ----

// x mod period in double, returned as a float in [0, period). TIME may be 1e6 s or more: a phase
// like TIME * speed must be wrapped before it becomes a float, or animation would move in steps of
// float's spacing (0.06 at 1e6). period must be > 0; a non-finite x gives 0.
float wrap_phase(double x, double period);

}  // namespace sdfreel::dm
