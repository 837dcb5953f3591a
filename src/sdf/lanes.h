#pragma once
// Eight float lanes, the CPU backend's packet of rays (one AVX2 register). Code written against
// the helpers below works on plain floats and glm vectors too, so a scene's distance function is
// one template for both paths: each lane performs exactly the scalar operations, in the same order,
// and gives the same bits (tests/sdf/lanes_test.cpp).
//
// Rules that keep lanes bit-identical to scalar code:
// - branches become select(mask, a, b) of both sides, computed with the scalar operations;
// - min/max/abs/floor/sqrt are the exact IEEE operations (dm:: on floats);
// - a mixed lane/uniform operation broadcasts the uniform: the rounding is the same.
// GCC vector extensions: they compile on any x86-64 target; built with -mavx2 they are single
// instructions (CMakeLists.txt, SDFREEL_ISA).
#include <cstdint>
#include <glm/glm.hpp>
#ifdef __AVX__
#include <immintrin.h>
#endif

#include "sdf/det_math.h"

namespace sdfreel {

constexpr int LANES = 8;
typedef float F8 __attribute__((vector_size(32)));
typedef int32_t M8 __attribute__((vector_size(32)));  // lane masks: -1 true, 0 false

inline F8 splat(float x) {
  return F8{x, x, x, x, x, x, x, x};
}
inline M8 splat_mask(bool b) {
  const int32_t v = b ? -1 : 0;
  return M8{v, v, v, v, v, v, v, v};
}
inline F8 load8(const float* p) {
  F8 v;
  __builtin_memcpy(&v, p, sizeof v);
  return v;
}
inline void store8(float* p, F8 v) {
  __builtin_memcpy(p, &v, sizeof v);
}

// ---- masks: scalar bools and lane masks share the names ----
inline float select(bool m, float a, float b) {
  return m ? a : b;
}
inline F8 select(M8 m, F8 a, F8 b) {
  return m ? a : b;
}
inline M8 select(M8 m, M8 a, M8 b) {
  return m ? a : b;
}
inline bool any(bool m) {
  return m;
}
inline bool all(bool m) {
  return m;
}
// Bit i set where lane i is: for a loop over the set lanes.
inline unsigned lane_bits(M8 m) {
#ifdef __AVX__
  return unsigned(_mm256_movemask_ps(reinterpret_cast<__m256>(m)));
#else
  unsigned bits = 0;
  for (int i = 0; i < LANES; ++i) bits |= m[i] != 0 ? 1u << i : 0u;
  return bits;
#endif
}
inline bool any(M8 m) {
  return lane_bits(m) != 0;
}
inline bool all(M8 m) {
  return lane_bits(m) == 0xffu;
}
// A per-frame flag or'ed into a per-point condition (a bool, or a mask of lanes).
inline bool either(bool uniform, bool m) {
  return uniform || m;
}
inline M8 either(bool uniform, M8 m) {
  return splat_mask(uniform) | m;
}
// Number of set lanes: what a masked loop adds to the ray statistics.
inline uint64_t count_lanes(M8 m) {
  return uint64_t(__builtin_popcount(lane_bits(m)));
}
// Lane i of a mask as a bool.
inline bool lane(M8 m, int i) {
  return m[i] != 0;
}

// ---- det_math on lanes: the same operations as the scalar functions in det_math.h ----
namespace dm {

inline F8 floor(F8 x) {
#ifdef __AVX__
  return reinterpret_cast<F8>(_mm256_floor_ps(reinterpret_cast<__m256>(x)));
#else
  for (int i = 0; i < LANES; ++i) x[i] = std::floor(x[i]);
  return x;
#endif
}
inline F8 sqrt(F8 x) {
#ifdef __AVX__
  return reinterpret_cast<F8>(_mm256_sqrt_ps(reinterpret_cast<__m256>(x)));
#else
  for (int i = 0; i < LANES; ++i) x[i] = std::sqrt(x[i]);
  return x;
#endif
}
inline F8 abs(F8 x) {
  return reinterpret_cast<F8>(reinterpret_cast<M8>(x) & 0x7fffffff);
}
inline F8 min(F8 a, F8 b) {
  return b < a ? b : a;
}
inline F8 min(F8 a, float b) {
  return min(a, splat(b));
}
inline F8 min(float a, F8 b) {
  return min(splat(a), b);
}
inline F8 max(F8 a, F8 b) {
  return a < b ? b : a;
}
inline F8 max(F8 a, float b) {
  return max(a, splat(b));
}
inline F8 max(float a, F8 b) {
  return max(splat(a), b);
}
inline F8 clamp(F8 x, float lo, float hi) {
  return min(max(x, lo), hi);
}
inline F8 fract(F8 x) {
  return x - floor(x);
}
inline F8 mix(F8 x, F8 y, F8 a) {
  return x * (1.0f - a) + y * a;
}
inline F8 mix(F8 x, F8 y, float a) {
  return x * (1.0f - a) + y * a;
}
inline F8 step(float edge, F8 x) {
  return select(x < edge, splat(0.0f), splat(1.0f));
}
inline F8 smoothstep(float e0, float e1, F8 x) {
  if (e0 == e1) return step(e0, x);
  const F8 t = clamp((x - e0) / (e1 - e0), 0.0f, 1.0f);
  return t * t * (3.0f - 2.0f * t);
}
inline F8 sign(F8 x) {
  return select(x > 0.0f, splat(1.0f), select(x < 0.0f, splat(-1.0f), splat(0.0f)));
}

// reduce_half_pi + the quadrant switch of sin/cos, with both kernels and a select. Equal to the
// scalar functions for every finite x (the quadrant is 0..3 there).
struct QuadrantReduced8 {
  F8 r, q;
};
inline QuadrantReduced8 reduce_half_pi(F8 x) {
  const F8 k = floor(x * TWO_OVER_PI + 0.5f);
  F8 r = x - k * PIO2_1;
  r = r - k * PIO2_2;
  r = r - k * PIO2_3;
  r = r - k * PIO2_4;
  r = clamp(r, -REDUCED_LIMIT, REDUCED_LIMIT);
  const F8 q = k - 4.0f * floor(k * 0.25f);
  return {r, q};
}
inline F8 sin_kernel(F8 r) {
  const F8 z = r * r;
  return ((-1.9515295891e-4f * z + 8.3321608736e-3f) * z - 1.6666654611e-1f) * z * r + r;
}
inline F8 cos_kernel(F8 r) {
  const F8 z = r * r;
  F8 y = ((2.443315711809948e-5f * z - 1.388731625493765e-3f) * z + 4.166664568298827e-2f) * z * z;
  y = y - 0.5f * z;
  return y + 1.0f;
}
inline F8 sin(F8 x) {
  const QuadrantReduced8 a = reduce_half_pi(x);
  const M8 odd = (a.q == 1.0f) | (a.q == 3.0f);
  const F8 v = select(odd, cos_kernel(a.r), sin_kernel(a.r));
  return select(a.q >= 2.0f, -v, v);
}
inline F8 cos(F8 x) {
  const QuadrantReduced8 a = reduce_half_pi(x);
  const M8 odd = (a.q == 1.0f) | (a.q == 3.0f);
  const F8 v = select(odd, sin_kernel(a.r), cos_kernel(a.r));
  // quadrants 1 and 2 are negative
  return select((a.q == 1.0f) | (a.q == 2.0f), -v, v);
}

}  // namespace dm

// table[i] in each lane: a load, no arithmetic, so the bits of the scalar table[i].
inline float gather(const float* table, int i) {
  return table[i];
}
inline F8 gather(const float* table, M8 i) {
#ifdef __AVX2__
  return reinterpret_cast<F8>(_mm256_i32gather_ps(table, reinterpret_cast<__m256i>(i), 4));
#else
  F8 v;
  for (int k = 0; k < LANES; ++k) v[k] = table[i[k]];
  return v;
#endif
}

inline M8 gather(const int32_t* table, M8 i) {
#ifdef __AVX2__
  return reinterpret_cast<M8>(_mm256_i32gather_epi32(table, reinterpret_cast<__m256i>(i), 4));
#else
  M8 v;
  for (int k = 0; k < LANES; ++k) v[k] = table[i[k]];
  return v;
#endif
}

// ---- vectors of lanes ----
struct V2x8 {
  F8 x, y;
};
struct V3x8 {
  F8 x, y, z;
  V3x8() = default;
  V3x8(F8 x_, F8 y_, F8 z_) : x(x_), y(y_), z(z_) {}
  explicit V3x8(const glm::vec3& v) : x(splat(v.x)), y(splat(v.y)), z(splat(v.z)) {}
  // Lane i as a glm vector.
  glm::vec3 lane(int i) const { return glm::vec3(x[i], y[i], z[i]); }
  void set_lane(int i, const glm::vec3& v) {
    x[i] = v.x;
    y[i] = v.y;
    z[i] = v.z;
  }
};

// Elementwise operators, the lane twin of glm's (vector op vector, vector op scalar).
#define SDFREEL_LANE_VEC_OPS(OP)                               \
  inline V3x8 operator OP(const V3x8& a, const V3x8& b) {      \
    return {a.x OP b.x, a.y OP b.y, a.z OP b.z};               \
  }                                                            \
  inline V3x8 operator OP(const V3x8& a, const glm::vec3& b) { \
    return {a.x OP b.x, a.y OP b.y, a.z OP b.z};               \
  }                                                            \
  inline V3x8 operator OP(const glm::vec3& a, const V3x8& b) { \
    return {a.x OP b.x, a.y OP b.y, a.z OP b.z};               \
  }                                                            \
  inline V3x8 operator OP(const V3x8& a, F8 s) {               \
    return {a.x OP s, a.y OP s, a.z OP s};                     \
  }                                                            \
  inline V3x8 operator OP(const V3x8& a, float s) {            \
    return {a.x OP s, a.y OP s, a.z OP s};                     \
  }                                                            \
  inline V2x8 operator OP(const V2x8& a, const V2x8& b) {      \
    return {a.x OP b.x, a.y OP b.y};                           \
  }                                                            \
  inline V2x8 operator OP(const V2x8& a, const glm::vec2& b) { \
    return {a.x OP b.x, a.y OP b.y};                           \
  }                                                            \
  inline V2x8 operator OP(const V2x8& a, F8 s) {               \
    return {a.x OP s, a.y OP s};                               \
  }                                                            \
  inline V2x8 operator OP(const V2x8& a, float s) {            \
    return {a.x OP s, a.y OP s};                               \
  }
SDFREEL_LANE_VEC_OPS(+)
SDFREEL_LANE_VEC_OPS(-)
SDFREEL_LANE_VEC_OPS(*)
SDFREEL_LANE_VEC_OPS(/)
#undef SDFREEL_LANE_VEC_OPS
inline V3x8 operator*(F8 s, const V3x8& a) {
  return {s * a.x, s * a.y, s * a.z};
}
inline V3x8 operator*(const glm::vec3& a, F8 s) {
  return {a.x * s, a.y * s, a.z * s};
}
inline V3x8 operator-(const V3x8& a) {
  return {-a.x, -a.y, -a.z};
}

inline V3x8 select(M8 m, const V3x8& a, const V3x8& b) {
  return {select(m, a.x, b.x), select(m, a.y, b.y), select(m, a.z, b.z)};
}

// ---- vector helpers shared by scalar (glm) and lane code, in glm's order of operations ----
// glm::dot(vec3): tmp = a * b; tmp.x + tmp.y + tmp.z.
inline float vdot(const glm::vec2& a, const glm::vec2& b) {
  return glm::dot(a, b);
}
inline float vdot(const glm::vec3& a, const glm::vec3& b) {
  return glm::dot(a, b);
}
inline F8 vdot(const V2x8& a, const V2x8& b) {
  return a.x * b.x + a.y * b.y;
}
inline F8 vdot(const V2x8& a, const glm::vec2& b) {
  return a.x * b.x + a.y * b.y;
}
inline F8 vdot(const V3x8& a, const V3x8& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
inline F8 vdot(const V3x8& a, const glm::vec3& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
inline F8 vdot(const glm::vec3& a, const V3x8& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
inline float vlength(const glm::vec2& v) {
  return glm::length(v);
}
inline float vlength(const glm::vec3& v) {
  return glm::length(v);
}
inline F8 vlength(const V2x8& v) {
  return dm::sqrt(vdot(v, v));
}
inline F8 vlength(const V3x8& v) {
  return dm::sqrt(vdot(v, v));
}
inline glm::vec2 vabs(const glm::vec2& v) {
  return glm::abs(v);
}
inline glm::vec3 vabs(const glm::vec3& v) {
  return glm::abs(v);
}
// glm::abs keeps the sign of -0 (x >= 0 ? x : -x), unlike dm::abs: mirrored for the lanes.
inline F8 glm_abs(F8 x) {
  return select(x >= 0.0f, x, -x);
}
inline V2x8 vabs(const V2x8& v) {
  return {glm_abs(v.x), glm_abs(v.y)};
}
inline V3x8 vabs(const V3x8& v) {
  return {glm_abs(v.x), glm_abs(v.y), glm_abs(v.z)};
}
inline glm::vec2 vmax(const glm::vec2& v, float b) {
  return glm::max(v, b);
}
inline glm::vec3 vmax(const glm::vec3& v, float b) {
  return glm::max(v, b);
}
inline V2x8 vmax(const V2x8& v, float b) {
  return {dm::max(v.x, b), dm::max(v.y, b)};
}
inline V3x8 vmax(const V3x8& v, float b) {
  return {dm::max(v.x, b), dm::max(v.y, b), dm::max(v.z, b)};
}
// A 2- or 3-vector of the same kind (glm or lanes) from components.
inline glm::vec2 vec2_of(float x, float y) {
  return glm::vec2(x, y);
}
inline V2x8 vec2_of(F8 x, F8 y) {
  return {x, y};
}
inline V2x8 vec2_of(F8 x, float y) {
  return {x, splat(y)};
}
inline glm::vec3 vec3_of(float x, float y, float z) {
  return glm::vec3(x, y, z);
}
inline V3x8 vec3_of(F8 x, F8 y, F8 z) {
  return {x, y, z};
}

}  // namespace sdfreel
