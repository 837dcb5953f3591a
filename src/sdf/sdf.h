#pragma once
// Signed distance primitives and operators after Inigo Quilez ("distance functions" article), as
// small pure float functions with GLSL's names and argument order, so that shaders/common can
// mirror them line for line. The 3D primitives and operators are templates over the point type:
// glm::vec3 (scalar path) or V3x8 (eight lanes, sdf/lanes.h), one source with the same operations
// in the same order for both, so lanes give the scalar bits. Every function is 1-Lipschitz (a bound
// or exact distance) and finite for finite input: square roots of rounding-negative values and
// divisions by zero are guarded.
#include <glm/glm.hpp>

#include "sdf/det_math.h"
#include "sdf/lanes.h"

namespace sdfreel {

// ---- helpers ----

// Length below which a vector has no usable direction.
constexpr float SAFE_NORMALIZE_MIN_LENGTH2 = 1e-30f;

// normalize() that never divides by zero: a (near-)zero vector maps to +Y (a tetrahedron normal
// whose taps cancel at a crease of min/max: tests/hard_cases/sdf_morph/crease_normals).
inline glm::vec3 safe_normalize(const glm::vec3& v) {
  const float len2 = glm::dot(v, v);
  if (!(len2 > SAFE_NORMALIZE_MIN_LENGTH2)) return glm::vec3(0.0f, 1.0f, 0.0f);
  return v / dm::sqrt(len2);
}

inline float dot2(const glm::vec2& v) {
  return glm::dot(v, v);
}
inline float dot2(const glm::vec3& v) {
  return glm::dot(v, v);
}

// Rotation about +Y by the angle whose cosine and sine are given (precompute them per frame).
template <class V>
inline V rotateY(const V& p, float c, float s) {
  return vec3_of(c * p.x + s * p.z, p.y, c * p.z - s * p.x);
}

// ---- 3D primitives (centred at the origin) ----

template <class V>
inline auto sdSphere(const V& p, float r) {
  return vlength(p) - r;
}

// b: half extents.
template <class V>
inline auto sdBox(const V& p, const glm::vec3& b) {
  const V q = vabs(p) - b;
  return vlength(vmax(q, 0.0f)) + dm::min(dm::max(q.x, dm::max(q.y, q.z)), 0.0f);
}

// b: half extents including the rounding; r: corner radius.
template <class V>
inline auto sdRoundBox(const V& p, const glm::vec3& b, float r) {
  const V q = vabs(p) - b + r;
  return vlength(vmax(q, 0.0f)) + dm::min(dm::max(q.x, dm::max(q.y, q.z)), 0.0f) - r;
}

// Ring in the xz plane: t.x major radius, t.y tube radius.
template <class V>
inline auto sdTorus(const V& p, const glm::vec2& t) {
  const auto q = vec2_of(vlength(vec2_of(p.x, p.z)) - t.x, p.y);
  return vlength(q) - t.y;
}

// Arc of a ring in the xy plane, symmetric about +Y, spanning the angle `an` either side of +Y;
// sc = (sin an, cos an). ra ring radius, rb tube radius.
template <class V>
inline auto sdCappedTorus(V p, const glm::vec2& sc, float ra, float rb) {
  p.x = dm::abs(p.x);
  const auto pxy = vec2_of(p.x, p.y);
  const auto k = select(sc.y * p.x > sc.x * p.y, vdot(pxy, sc), vlength(pxy));
  // The radicand is |p - nearest arc point|^2 >= 0 up to rounding.
  return dm::sqrt(dm::max(vdot(p, p) + ra * ra - 2.0f * ra * k, 0.0f)) - rb;
}

// Vertical cylinder: h half height, r radius.
template <class V>
inline auto sdCappedCylinder(const V& p, float h, float r) {
  const auto d = vabs(vec2_of(vlength(vec2_of(p.x, p.z)), p.y)) - glm::vec2(r, h);
  return dm::min(dm::max(d.x, d.y), 0.0f) + vlength(vmax(d, 0.0f));
}

// The lantern rods of seed 000: a capped cylinder moved by `offset` in the xz plane.
template <class V>
inline auto sdCappedCylinderOffset(const V& p, float h, float r, const glm::vec2& offset) {
  return sdCappedCylinder(p - glm::vec3(offset.x, 0.0f, offset.y), h, r);
}

// Plane through the points with dot(p, n) = -h; n must be unit length.
template <class V>
inline auto sdPlane(const V& p, const glm::vec3& n, float h) {
  return vdot(p, n) + h;
}

// Unsigned distance to the segment ab (a == b is a point).
inline float sdSegment(const glm::vec3& p, const glm::vec3& a, const glm::vec3& b) {
  const glm::vec3 pa = p - a, ba = b - a;
  const float bb = glm::dot(ba, ba);
  const float h = bb > 0.0f ? dm::clamp(glm::dot(pa, ba) / bb, 0.0f, 1.0f) : 0.0f;
  return glm::length(pa - ba * h);
}

inline float sdCapsule(const glm::vec3& p, const glm::vec3& a, const glm::vec3& b, float r) {
  return sdSegment(p, a, b) - r;
}

// ---- 2D primitives ----

inline float sdCircle(const glm::vec2& p, float r) {
  return glm::length(p) - r;
}

inline float sdSegment(const glm::vec2& p, const glm::vec2& a, const glm::vec2& b) {
  const glm::vec2 pa = p - a, ba = b - a;
  const float bb = glm::dot(ba, ba);
  const float h = bb > 0.0f ? dm::clamp(glm::dot(pa, ba) / bb, 0.0f, 1.0f) : 0.0f;
  return glm::length(pa - ba * h);
}

inline float sdBox2(const glm::vec2& p, const glm::vec2& b) {
  const glm::vec2 q = glm::abs(p) - b;
  return glm::length(glm::max(q, 0.0f)) + dm::min(dm::max(q.x, q.y), 0.0f);
}

// Rounded rectangle: b half extents including the rounding, r corner radius.
inline float sdRoundRect(const glm::vec2& p, const glm::vec2& b, float r) {
  return sdBox2(p, b - glm::vec2(r)) - r;
}

// ---- operators ----

template <class F>
inline F opUnion(F d1, F d2) {
  return dm::min(d1, d2);
}
// d2 with d1 carved out of it (Quilez's argument order).
template <class F>
inline F opSubtraction(F d1, F d2) {
  return dm::max(-d1, d2);
}
template <class F>
inline F opIntersection(F d1, F d2) {
  return dm::max(d1, d2);
}

// Polynomial smooth minimum with blend radius k; k <= 0 is the hard operation (no division by 0:
// tests/hard_cases/sdf_morph/smooth_union_k0).
template <class F>
inline F opSmoothUnion(F d1, F d2, float k) {
  if (!(k > 0.0f)) return opUnion(d1, d2);
  const F h = dm::clamp(0.5f + 0.5f * (d2 - d1) / k, 0.0f, 1.0f);
  return dm::mix(d2, d1, h) - k * h * (1.0f - h);
}

template <class F>
inline F opSmoothSubtraction(F d1, F d2, float k) {
  if (!(k > 0.0f)) return opSubtraction(d1, d2);
  const F h = dm::clamp(0.5f - 0.5f * (d2 + d1) / k, 0.0f, 1.0f);
  return dm::mix(d2, -d1, h) + k * h * (1.0f - h);
}

template <class F>
inline F opSmoothIntersection(F d1, F d2, float k) {
  if (!(k > 0.0f)) return opIntersection(d1, d2);
  const F h = dm::clamp(0.5f - 0.5f * (d2 - d1) / k, 0.0f, 1.0f);
  return dm::mix(d2, d1, h) + k * h * (1.0f - h);
}

// Shell of thickness 2t around the surface.
template <class F>
inline F opOnion(F d, float t) {
  return dm::abs(d) - t;
}
// Rounds a shape by growing it by r (shrink the primitive by r first to keep its size).
template <class F>
inline F opRound(F d, float r) {
  return d - r;
}
// Mirror into the +x +z quadrant (four copies for the price of one).
template <class V>
inline V opSymXZ(const V& p) {
  return vec3_of(dm::abs(p.x), p.y, dm::abs(p.z));
}

}  // namespace sdfreel
