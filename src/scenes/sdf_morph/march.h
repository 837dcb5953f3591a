#pragma once
// sdf_morph marching constants and the small per-ray helpers (ray spans, epsilons, biases) that
// the scalar path (sdf_morph/render.cpp) and the eight-lane path (sdf_morph/lanes.cpp) share.
#include <glm/glm.hpp>

#include "scenes/sdf_morph/geometry.h"
#include "scenes/sdf_morph/uniforms.h"
#include "sdf/det_math.h"

namespace sdfreel::sdf_morph {

constexpr float MIN_HIT_EPS = 1e-5f;
constexpr float MIN_NORMAL_EPS = 1e-4f;
constexpr float SURFACE_BIAS_FACTOR = 2.0f;  // secondary rays start this many hit eps off
constexpr float MIN_SURFACE_BIAS = 2e-3f;
constexpr float NO_HIT = -1.0f;
constexpr float MISS_SPAN = 1e30f;
// MarchSettings::hit_mask output: which marched surface the primary ray hit.
constexpr float HIT_ID_NONE = 0.0f;
constexpr float HIT_ID_OBJECT = 1.0f;
constexpr float HIT_ID_PEDESTAL = 2.0f;

constexpr float SHADOW_TMIN = 0.01f;
constexpr float SHADOW_HIT_EPS = 1e-3f;
constexpr float SHADOW_FIRST_PH = 1e10f;  // "previous h" before the first step: no estimate yet
constexpr float SHADOW_MIN_DENOM = 1e-6f;

constexpr int AO_TAPS = 5;
constexpr float AO_START = 0.01f;
constexpr float AO_SPAN = 0.12f;
constexpr float AO_FALLOFF = 0.95f;
constexpr float AO_STRENGTH = 3.0f;
constexpr float AO_REACH = AO_START + AO_SPAN;

// Distance along the normal of ambient occlusion tap i.
inline float aoTapHeight(int i) {
  return AO_START + AO_SPAN * float(i) / float(AO_TAPS - 1);
}

// (t_enter, t_exit) of the ray with a sphere; (MISS_SPAN, -MISS_SPAN) when it misses. The
// discriminant is r^2 - (distance of the centre from the ray)^2, not b^2 - c, which would cancel
// catastrophically for a camera far away (tests/hard_cases/sdf_morph/far_camera_object).
inline glm::vec2 intersectSphere(const glm::vec3& ro, const glm::vec3& rd, const glm::vec3& center,
                                 float radius) {
  const glm::vec3 oc = ro - center;
  const float b = glm::dot(oc, rd);
  const glm::vec3 q = oc - b * rd;
  const float disc = radius * radius - glm::dot(q, q);
  if (disc < 0.0f) return glm::vec2(MISS_SPAN, -MISS_SPAN);
  const float s = dm::sqrt(disc);
  return glm::vec2(-b - s, -b + s);
}

// Distance to the floor plane y = 0 along the ray, or NO_HIT.
inline float intersectFloor(const glm::vec3& ro, const glm::vec3& rd) {
  if (rd.y == 0.0f) return NO_HIT;
  const float t = -ro.y / rd.y;
  return t > 0.0f ? t : NO_HIT;
}

inline float hitEps(float eps_per_t, float t, const MorphUniforms& u) {
  return u.naive ? u.hit_eps : dm::max(MIN_HIT_EPS, eps_per_t * t);
}
inline float normalEps(float pixel_angle, float t, const MorphUniforms& u) {
  return u.naive ? u.normal_eps : dm::max(MIN_NORMAL_EPS, u.normal_eps * pixel_angle * t);
}
// The part of a ray worth marching: inside the sphere around object and pedestal, or (naive
// preset, no bounding volumes) everything up to max_dist.
inline glm::vec2 groupSpan(const glm::vec3& ro, const glm::vec3& rd, const MorphUniforms& u) {
  if (u.naive) return glm::vec2(0.0f, u.max_dist);
  return intersectSphere(ro, rd, groupBoundCenter(), GROUP_BOUND_RADIUS);
}
inline float surfaceBias(float eps) {
  return dm::max(MIN_SURFACE_BIAS, SURFACE_BIAS_FACTOR * eps);
}

inline glm::vec3 reflectDir(const glm::vec3& d, const glm::vec3& n) {
  return d - 2.0f * glm::dot(n, d) * n;
}

// A surface point gets a soft shadow when it faces the key light, and ambient occlusion when an
// occluder may lie within AO_REACH (always for the naive preset, which has no bounds).
// Templates over the point type: a bool for one point, a lane mask for V3x8.
template <class V>
inline auto needsShadow(const V& n, const MorphUniforms& u) {
  return vdot(n, u.boxes[0].dir) > 0.0f;
}
template <class V>
inline auto needsOcclusion(const V& p, const MorphUniforms& u) {
  return either(u.naive, vlength(p - groupBoundCenter()) < GROUP_BOUND_RADIUS + AO_REACH);
}

}  // namespace sdfreel::sdf_morph
