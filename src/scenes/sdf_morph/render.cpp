#include "scenes/sdf_morph/render.h"

#include "scenes/common/relaxed_march.h"
#include "scenes/common/surface_output.h"
#include "scenes/sdf_morph/environment.h"
#include "scenes/sdf_morph/geometry.h"
#include "scenes/sdf_morph/march.h"
#include "sdf/det_math.h"
#include "sdf/sdf.h"

namespace sdfreel::sdf_morph {
namespace {

using glm::vec2;
using glm::vec3;

const vec3 KEY_COLOR(1.0f, 0.96f, 0.9f);
const vec3 AMBIENT_SKY(0.22f, 0.22f, 0.24f);
const vec3 AMBIENT_GROUND(0.08f, 0.075f, 0.07f);

const vec3 PEDESTAL_ALBEDO(0.5f, 0.485f, 0.47f);
constexpr float PEDESTAL_F0 = 0.03f;  // satin stone: a faint Fresnel reflection
const vec3 FLOOR_ALBEDO(0.2f, 0.19f, 0.18f);
constexpr float FLOOR_FADE_START = 5.0f;  // horizontal distance where the floor starts to fade
constexpr float FLOOR_FADE_END = 20.0f;   // ... into the backdrop (a cyclorama with no seam)

// Sphere tracing of mapScene from tmin to tmax with over-relaxation (Keinert et al. 2014): steps
// of step_factor * d, and when the unbounding spheres of two steps stop overlapping, one step
// back and plain steps from there. The hit threshold grows with the path length: eps_per_t *
// (t_before + t), t_before being the length of the path before this ray (for reflections).
// Returns t of the hit, or NO_HIT. A ray that runs out of steps counts as a hit where it
// stopped (it is creeping along a surface) and is counted in stats.capped.
// The naive preset: plain steps and a fixed world-space threshold u.hit_eps.
float march(const vec3& ro, const vec3& rd, float tmin, float tmax, int max_steps, float eps_per_t,
            float t_before, const MorphUniforms& u, RayStats& stats) {
  const RelaxedMarchSettings s{max_steps, u.naive, u.step_factor, u.hit_eps, MIN_HIT_EPS, NO_HIT};
  return relaxed_march([&](const vec3& p) { return mapScene(p, u, stats); }, ro, rd, tmin, tmax,
                       eps_per_t, t_before, s, stats);
}

float schlick(float cos_theta, float f0) {
  const float x = 1.0f - dm::clamp(cos_theta, 0.0f, 1.0f);
  const float x2 = x * x;
  return f0 + (1.0f - f0) * (x2 * x2 * x);
}

vec3 ambientLight(const vec3& n, const MorphUniforms& u) {
  return u.env_intensity * dm::mix(AMBIENT_GROUND, AMBIENT_SKY, 0.5f + 0.5f * n.y);
}

// Key light (from the key soft box's direction, shadowed) plus ambient, times albedo.
vec3 diffuseLight(const vec3& albedo, const vec3& n, float shadow, float ao,
                  const MorphUniforms& u) {
  const float ndl = dm::max(glm::dot(n, u.boxes[0].dir), 0.0f);
  return albedo * (u.key_intensity * ndl * shadow * KEY_COLOR + ambientLight(n, u) * ao);
}

// Shadow and occlusion at a surface point; `full` = false (inside reflections) skips both.
// Occlusion needs an occluder within AO_REACH: points farther from the group skip it.
void occlusion(const vec3& p, const vec3& n, float bias, bool full, const MorphUniforms& u,
               RayStats& stats, float& shadow, float& ao) {
  shadow = 1.0f;
  ao = 1.0f;
  if (!full) return;
  if (needsShadow(n, u)) shadow = softShadow(p + n * bias, u.boxes[0].dir, u, stats);
  if (needsOcclusion(p, u)) ao = ambientOcclusion(p, n, u, stats);
}

vec3 shadeFloor(const vec3& p, const vec3& rd, float bias, bool full, const MorphUniforms& u,
                RayStats& stats) {
  float shadow, ao;
  occlusion(p, vec3(0.0f, 1.0f, 0.0f), bias, full, u, stats, shadow, ao);
  return shadeFloorLit(p, shadow, ao, environment(rd, u), u);
}

vec3 shadePedestal(const vec3& p, const vec3& n, const vec3& rd, float bias, bool full,
                   const MorphUniforms& u, RayStats& stats) {
  float shadow, ao;
  occlusion(p, n, bias, full, u, stats, shadow, ao);
  return shadePedestalLit(n, rd, shadow, ao, environment(reflectDir(rd, n), u), u);
}

vec3 shadeObject(const vec3& p, const vec3& n, const vec3& rd, const vec3& reflection, float bias,
                 bool full, const MorphUniforms& u, RayStats& stats) {
  float shadow, ao;
  occlusion(p, n, bias, full, u, stats, shadow, ao);
  return shadeObjectLit(n, rd, reflection, shadow, ao, u);
}

// What the mirror sees from p along r: the pedestal, the object itself (e.g. the mug's inside),
// the floor, or the studio. Surfaces found here are shaded without further bounces or shadows.
vec3 traceReflection(const vec3& p, const vec3& n, const vec3& r, float t_before, float eps_per_t,
                     float pixel_angle, const MorphUniforms& u, RayStats& stats) {
  const ReflectionSpan span = reflectionSpan(p, n, r, t_before, eps_per_t, u);
  if (span.t0 < span.t1) {
    const float t =
        march(span.ro, r, span.t0, span.t1, u.reflect_steps, eps_per_t, t_before, u, stats);
    if (t != NO_HIT) {
      const vec3 q = span.ro + r * t;
      const float e = normalEps(pixel_angle, t_before + t, u);
      const vec3 nq = calcNormal(q, e, u, stats);
      return shadeReflectionHit(nq, r, isObject(q, u), environment(reflectDir(r, nq), u), u);
    }
  }
  return shadeReflectionMiss(span, r, environment(r, u), u);
}

}  // namespace

// IQ's 5-tap ambient occlusion along the normal.
float ambientOcclusion(const vec3& p, const vec3& n, const MorphUniforms& u, RayStats& stats) {
  float occ = 0.0f;
  float scale = 1.0f;
  for (int i = 0; i < AO_TAPS; ++i) {
    const float h = aoTapHeight(i);
    const float d = mapScene(p + n * h, u, stats);
    occ += (h - d) * scale;
    scale *= AO_FALLOFF;
  }
  return aoFromSum(occ);
}

float aoFromSum(float occ) {
  return dm::clamp(1.0f - AO_STRENGTH * occ, 0.0f, 1.0f);
}

vec3 shadeFloorLit(const vec3& p, float shadow, float ao, const vec3& env_rd,
                   const MorphUniforms& u) {
  const vec3 n(0.0f, 1.0f, 0.0f);
  const vec3 col = diffuseLight(FLOOR_ALBEDO, n, shadow, ao, u);
  const float fade = dm::smoothstep(FLOOR_FADE_START, FLOOR_FADE_END, glm::length(vec2(p.x, p.z)));
  return dm::mix(col, env_rd, fade);
}

vec3 shadePedestalLit(const vec3& n, const vec3& rd, float shadow, float ao, const vec3& env_mirror,
                      const MorphUniforms& u) {
  const vec3 diffuse = diffuseLight(PEDESTAL_ALBEDO, n, shadow, ao, u);
  const float f = schlick(glm::dot(n, -rd), PEDESTAL_F0);
  return dm::mix(diffuse, env_mirror * ao, f);
}

// The object: coloured diffuse base mixed with the mirror reflection by Schlick's Fresnel term.
vec3 shadeObjectLit(const vec3& n, const vec3& rd, const vec3& reflection, float shadow, float ao,
                    const MorphUniforms& u) {
  const vec3 diffuse = diffuseLight(u.base_color, n, shadow, ao, u);
  const float f = schlick(glm::dot(n, -rd), u.reflectivity);
  return dm::mix(diffuse, reflection, f);
}

PrimarySpan primarySpan(const Ray& ray, const MorphUniforms& u) {
  PrimarySpan s;
  s.eps_per_t = u.hit_eps * ray.pixel_angle;
  s.t_floor = intersectFloor(ray.origin, ray.dir);
  s.floor_visible = s.t_floor > 0.0f && s.t_floor < u.max_dist;
  const float tmax = s.floor_visible ? s.t_floor : u.max_dist;
  const vec2 span = groupSpan(ray.origin, ray.dir, u);
  s.t0 = dm::max(span.x, 0.0f);
  s.t1 = dm::min(span.y, tmax);
  return s;
}

ReflectionSpan reflectionSpan(const vec3& p, const vec3& n, const vec3& r, float t_before,
                              float eps_per_t, const MorphUniforms& u) {
  ReflectionSpan s;
  s.ro = p + n * surfaceBias(hitEps(eps_per_t, t_before, u));
  s.t_floor = intersectFloor(s.ro, r);
  const float tmax = s.t_floor > 0.0f ? dm::min(s.t_floor, u.max_dist) : u.max_dist;
  const vec2 span = groupSpan(s.ro, r, u);
  s.t0 = dm::max(span.x, 0.0f);
  s.t1 = dm::min(span.y, tmax);
  return s;
}

vec3 shadeReflectionHit(const vec3& nq, const vec3& r, bool object, const vec3& env_mirror,
                        const MorphUniforms& u) {
  if (object) return shadeObjectLit(nq, r, env_mirror, 1.0f, 1.0f, u);
  return shadePedestalLit(nq, r, 1.0f, 1.0f, env_mirror, u);
}

vec3 shadeReflectionMiss(const ReflectionSpan& span, const vec3& r, const vec3& env_r,
                         const MorphUniforms& u) {
  if (span.t_floor > 0.0f && span.t_floor < u.max_dist)
    return shadeFloorLit(span.ro + r * span.t_floor, 1.0f, 1.0f, env_r, u);
  return env_r;
}

vec3 environment(const vec3& d, const MorphUniforms& u) {
  return studio(d, u);
}

float softShadow(const vec3& ro, const vec3& rd, const MorphUniforms& u, RayStats& stats) {
  // Only the pedestal group casts shadows: march just the part of the ray inside its sphere.
  const vec2 span = groupSpan(ro, rd, u);
  if (span.y <= 0.0f) return 1.0f;
  float t = dm::max(SHADOW_TMIN, span.x);
  float res = 1.0f;
  float ph = SHADOW_FIRST_PH;
  for (int i = 0; i < u.shadow_steps && t < span.y; ++i) {
    stats.steps += 1;
    stats.sdf_evals += 1;
    // Only exact distances may enter the penumbra estimate: the bounding sphere's lower bound
    // would cast a faint shadow of the sphere itself. Where only the bound is known, the true
    // distance exceeds the margin t / k, so that sample could not darken the result anyway.
    const float margin = dm::max(OBJECT_BOUND_MARGIN, t / u.shadow_k);
    bool exact;
    const float h = mapSceneBounded(ro + rd * t, u, margin, exact);
    if (h < SHADOW_HIT_EPS) return 0.0f;
    if (exact) {
      // Where the last two unbounding spheres intersect: a better estimate of the closest
      // approach than h alone (IQ, "soft shadows in raymarched SDFs", improved technique).
      const float y = h * h / (2.0f * ph);
      const float d = dm::sqrt(dm::max(h * h - y * y, 0.0f));
      res = dm::min(res, u.shadow_k * d / dm::max(t - y, SHADOW_MIN_DENOM));
      ph = h;
    } else {
      ph = SHADOW_FIRST_PH;  // a bound is no history for the next estimate
    }
    t += h;
  }
  res = dm::clamp(res, 0.0f, 1.0f);
  return res * res * (3.0f - 2.0f * res);
}

vec3 calcNormal(const vec3& p, float e, const MorphUniforms& u, RayStats& stats) {
  const vec3 a(1.0f, -1.0f, -1.0f), b(-1.0f, -1.0f, 1.0f), c(-1.0f, 1.0f, -1.0f),
      d(1.0f, 1.0f, 1.0f);
  return safe_normalize(a * mapScene(p + a * e, u, stats) + b * mapScene(p + b * e, u, stats) +
                        c * mapScene(p + c * e, u, stats) + d * mapScene(p + d * e, u, stats));
}

vec3 sceneRadiance(const Ray& ray, const MorphUniforms& u, RayStats& stats) {
  const vec3 ro = ray.origin, rd = ray.dir;
  const PrimarySpan s = primarySpan(ray, u);
  if (s.t0 < s.t1) {
    const float t = march(ro, rd, s.t0, s.t1, u.max_steps, s.eps_per_t, 0.0f, u, stats);
    if (t != NO_HIT) {
      const vec3 p = ro + rd * t;
      if (u.hit_mask) return vec3(isObject(p, u) ? HIT_ID_OBJECT : HIT_ID_PEDESTAL);
      const float e = normalEps(ray.pixel_angle, t, u);
      const vec3 n = calcNormal(p, e, u, stats);
      if (u.surface != SURFACE_COLOUR) return surfaceOutput(u.surface, t, n);
      const float bias = surfaceBias(hitEps(s.eps_per_t, t, u));
      if (isObject(p, u)) {
        const vec3 refl =
            traceReflection(p, n, reflectDir(rd, n), t, s.eps_per_t, ray.pixel_angle, u, stats);
        return shadeObject(p, n, rd, refl, bias, true, u, stats);
      }
      return shadePedestal(p, n, rd, bias, true, u, stats);
    }
  }
  if (u.hit_mask) return vec3(HIT_ID_NONE);  // the floor is a plane, not marched
  if (u.surface != SURFACE_COLOUR)
    return s.floor_visible ? surfaceOutput(u.surface, s.t_floor, vec3(0.0f, 1.0f, 0.0f))
                           : noSurface(u.surface);
  if (s.floor_visible) {
    const float bias = surfaceBias(hitEps(s.eps_per_t, s.t_floor, u));
    return shadeFloor(ro + rd * s.t_floor, rd, bias, true, u, stats);
  }
  return environment(rd, u);
}

}  // namespace sdfreel::sdf_morph
