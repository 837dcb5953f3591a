#include "scenes/sdf_morph_render.h"

#include "scenes/sdf_morph_geometry.h"
#include "sdf/det_math.h"
#include "sdf/sdf.h"

namespace sdfreel::sdf_morph {
namespace {

using glm::vec2;
using glm::vec3;

// ---- studio look (linear Rec.709) ----
const vec3 WALL_LOW(0.16f, 0.155f, 0.15f);            // walls near the horizon
const vec3 WALL_HIGH(0.03f, 0.032f, 0.036f);          // towards the ceiling
const vec3 FLOOR_FAR(0.085f, 0.08f, 0.075f);          // below the horizon
constexpr float WALL_GRADIENT_TOP = 0.6f;             // d.y where the wall reaches WALL_HIGH
constexpr float HORIZON_SOFTNESS = 0.04f;             // d.y half width of the floor/wall transition
const vec3 BACKDROP_DIR(0.0f, 0.148340f, 0.988936f);  // light pool on the wall behind the object
const vec3 BACKDROP_GLOW(0.22f, 0.21f, 0.19f);        // falls off as cos^6 from BACKDROP_DIR
constexpr float SOFTBOX_MIN_COS = 0.05f;      // boxes are invisible beyond ~87 degrees off-axis
constexpr float SOFTBOX_EDGE = 0.02f;         // soft edge width on the unit-distance plane
constexpr float SOFTBOX_GLOW = 0.04f;         // faint halo around each box (diffuser spill)
constexpr float SOFTBOX_GLOW_FALLOFF = 8.0f;  // halo: 1 / (1 + (falloff * distance)^2)

const vec3 KEY_COLOR(1.0f, 0.96f, 0.9f);
const vec3 AMBIENT_SKY(0.22f, 0.22f, 0.24f);
const vec3 AMBIENT_GROUND(0.08f, 0.075f, 0.07f);

const vec3 PEDESTAL_ALBEDO(0.5f, 0.485f, 0.47f);
constexpr float PEDESTAL_F0 = 0.03f;  // satin stone: a faint Fresnel reflection
const vec3 FLOOR_ALBEDO(0.2f, 0.19f, 0.18f);
constexpr float FLOOR_FADE_START = 5.0f;  // horizontal distance where the floor starts to fade
constexpr float FLOOR_FADE_END = 20.0f;   // ... into the backdrop (a cyclorama with no seam)

// ---- marching ----
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

// (t_enter, t_exit) of the ray with a sphere; (MISS_SPAN, -MISS_SPAN) when it misses. The
// discriminant is r^2 - (distance of the centre from the ray)^2, not b^2 - c, which would cancel
// catastrophically for a camera far away (tests/hard_cases/far_camera_object).
vec2 intersectSphere(const vec3& ro, const vec3& rd, const vec3& center, float radius) {
  const vec3 oc = ro - center;
  const float b = glm::dot(oc, rd);
  const vec3 q = oc - b * rd;
  const float disc = radius * radius - glm::dot(q, q);
  if (disc < 0.0f) return vec2(MISS_SPAN, -MISS_SPAN);
  const float s = dm::sqrt(disc);
  return vec2(-b - s, -b + s);
}

// Distance to the floor plane y = 0 along the ray, or NO_HIT.
float intersectFloor(const vec3& ro, const vec3& rd) {
  if (rd.y == 0.0f) return NO_HIT;
  const float t = -ro.y / rd.y;
  return t > 0.0f ? t : NO_HIT;
}

// Sphere tracing of mapScene from tmin to tmax with over-relaxation (Keinert et al. 2014): steps
// of step_factor * d, and when the unbounding spheres of two steps stop overlapping, one step
// back and plain steps from there. The hit threshold grows with the path length: eps_per_t *
// (t_before + t), t_before being the length of the path before this ray (for reflections).
// Returns t of the hit, or NO_HIT. A ray that runs out of steps counts as a hit where it
// stopped (it is creeping along a surface) and is counted in stats.capped.
// The naive preset: plain steps and a fixed world-space threshold u.hit_eps.
float march(const vec3& ro, const vec3& rd, float tmin, float tmax, int max_steps, float eps_per_t,
            float t_before, const MorphUniforms& u, RayStats& stats) {
  float t = tmin;
  float omega = u.naive ? 1.0f : u.step_factor;
  float prev_d = 0.0f;
  float step = 0.0f;
  for (int i = 0; i < max_steps; ++i) {
    stats.steps += 1;
    const float d = mapScene(ro + rd * t, u, stats);
    if (omega > 1.0f && dm::abs(d) + prev_d < step) {
      t += prev_d - step;  // back to the previous point plus a plain step
      step = prev_d;
      omega = 1.0f;
      continue;
    }
    const float eps = u.naive ? u.hit_eps : dm::max(MIN_HIT_EPS, eps_per_t * (t_before + t));
    // An eye inside the object sees d < 0 at once: a hit at tmin
    // (tests/hard_cases/inside_object).
    if (d < eps) return t;
    step = d * omega;
    prev_d = d;
    t += step;
    if (t > tmax) {
      // Only a plain step may conclude "nothing before tmax": a relaxed one may have jumped
      // over a surface just in front of it (the pedestal's foot before the floor).
      if (omega <= 1.0f || t - step + d > tmax) return NO_HIT;
      t += d - step;
      step = d;
      omega = 1.0f;
    }
  }
  stats.capped += 1;
  return t;
}

float hitEps(float eps_per_t, float t, const MorphUniforms& u) {
  return u.naive ? u.hit_eps : dm::max(MIN_HIT_EPS, eps_per_t * t);
}
float normalEps(float pixel_angle, float t, const MorphUniforms& u) {
  return u.naive ? u.normal_eps : dm::max(MIN_NORMAL_EPS, u.normal_eps * pixel_angle * t);
}
// The part of a ray worth marching: inside the sphere around object and pedestal, or (naive
// preset, no bounding volumes) everything up to max_dist.
vec2 groupSpan(const vec3& ro, const vec3& rd, const MorphUniforms& u) {
  if (u.naive) return vec2(0.0f, u.max_dist);
  return intersectSphere(ro, rd, groupBoundCenter(), GROUP_BOUND_RADIUS);
}
float surfaceBias(float eps) {
  return dm::max(MIN_SURFACE_BIAS, SURFACE_BIAS_FACTOR * eps);
}

vec3 reflectDir(const vec3& d, const vec3& n) {
  return d - 2.0f * glm::dot(n, d) * n;
}

float schlick(float cos_theta, float f0) {
  const float x = 1.0f - dm::clamp(cos_theta, 0.0f, 1.0f);
  const float x2 = x * x;
  return f0 + (1.0f - f0) * (x2 * x2 * x);
}

vec3 softBox(const vec3& d, const SoftBox& box) {
  const float c = glm::dot(d, box.dir);
  if (c <= SOFTBOX_MIN_COS) return vec3(0.0f);
  const vec2 uv = vec2(glm::dot(d, box.u), glm::dot(d, box.v)) / c;
  const float sd = sdRoundRect(uv, box.half_size, box.corner);
  const float core = 1.0f - dm::smoothstep(-SOFTBOX_EDGE, SOFTBOX_EDGE, sd);
  const float g = SOFTBOX_GLOW_FALLOFF * dm::max(sd, 0.0f);
  const float glow = SOFTBOX_GLOW / (1.0f + g * g);
  return box.radiance * (core + glow);
}

// IQ's 5-tap ambient occlusion along the normal.
float ambientOcclusion(const vec3& p, const vec3& n, const MorphUniforms& u, RayStats& stats) {
  float occ = 0.0f;
  float scale = 1.0f;
  for (int i = 0; i < AO_TAPS; ++i) {
    const float h = AO_START + AO_SPAN * float(i) / float(AO_TAPS - 1);
    const float d = mapScene(p + n * h, u, stats);
    occ += (h - d) * scale;
    scale *= AO_FALLOFF;
  }
  return dm::clamp(1.0f - AO_STRENGTH * occ, 0.0f, 1.0f);
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
  if (glm::dot(n, u.boxes[0].dir) > 0.0f)
    shadow = softShadow(p + n * bias, u.boxes[0].dir, u, stats);
  if (u.naive || glm::length(p - groupBoundCenter()) < GROUP_BOUND_RADIUS + AO_REACH)
    ao = ambientOcclusion(p, n, u, stats);
}

vec3 shadeFloor(const vec3& p, const vec3& rd, float bias, bool full, const MorphUniforms& u,
                RayStats& stats) {
  const vec3 n(0.0f, 1.0f, 0.0f);
  float shadow, ao;
  occlusion(p, n, bias, full, u, stats, shadow, ao);
  const vec3 col = diffuseLight(FLOOR_ALBEDO, n, shadow, ao, u);
  const float fade = dm::smoothstep(FLOOR_FADE_START, FLOOR_FADE_END, glm::length(vec2(p.x, p.z)));
  return dm::mix(col, environment(rd, u), fade);
}

vec3 shadePedestal(const vec3& p, const vec3& n, const vec3& rd, float bias, bool full,
                   const MorphUniforms& u, RayStats& stats) {
  float shadow, ao;
  occlusion(p, n, bias, full, u, stats, shadow, ao);
  const vec3 diffuse = diffuseLight(PEDESTAL_ALBEDO, n, shadow, ao, u);
  const float f = schlick(glm::dot(n, -rd), PEDESTAL_F0);
  return dm::mix(diffuse, environment(reflectDir(rd, n), u) * ao, f);
}

// The object: coloured diffuse base mixed with the mirror reflection by Schlick's Fresnel term.
vec3 shadeObject(const vec3& p, const vec3& n, const vec3& rd, const vec3& reflection, float bias,
                 bool full, const MorphUniforms& u, RayStats& stats) {
  float shadow, ao;
  occlusion(p, n, bias, full, u, stats, shadow, ao);
  const vec3 diffuse = diffuseLight(u.base_color, n, shadow, ao, u);
  const float f = schlick(glm::dot(n, -rd), u.reflectivity);
  return dm::mix(diffuse, reflection, f);
}

// What the mirror sees from p along r: the pedestal, the object itself (e.g. the mug's inside),
// the floor, or the studio. Surfaces found here are shaded without further bounces or shadows.
vec3 traceReflection(const vec3& p, const vec3& n, const vec3& r, float t_before, float eps_per_t,
                     float pixel_angle, const MorphUniforms& u, RayStats& stats) {
  const vec3 ro = p + n * surfaceBias(hitEps(eps_per_t, t_before, u));
  const float t_floor = intersectFloor(ro, r);
  const float tmax = t_floor > 0.0f ? dm::min(t_floor, u.max_dist) : u.max_dist;
  const vec2 span = groupSpan(ro, r, u);
  const float t0 = dm::max(span.x, 0.0f), t1 = dm::min(span.y, tmax);
  if (t0 < t1) {
    const float t = march(ro, r, t0, t1, u.reflect_steps, eps_per_t, t_before, u, stats);
    if (t != NO_HIT) {
      const vec3 q = ro + r * t;
      const float e = normalEps(pixel_angle, t_before + t, u);
      const vec3 nq = calcNormal(q, e, u, stats);
      if (isObject(q, u))
        return shadeObject(q, nq, r, environment(reflectDir(r, nq), u), 0.0f, false, u, stats);
      return shadePedestal(q, nq, r, 0.0f, false, u, stats);
    }
  }
  if (t_floor > 0.0f && t_floor < u.max_dist)
    return shadeFloor(ro + r * t_floor, r, 0.0f, false, u, stats);
  return environment(r, u);
}

}  // namespace

vec3 environment(const vec3& d, const MorphUniforms& u) {
  const vec3 wall = dm::mix(WALL_LOW, WALL_HIGH, dm::smoothstep(0.0f, WALL_GRADIENT_TOP, d.y));
  vec3 col = dm::mix(FLOOR_FAR, wall, dm::smoothstep(-HORIZON_SOFTNESS, HORIZON_SOFTNESS, d.y));
  const float b = dm::max(glm::dot(d, BACKDROP_DIR), 0.0f);
  const float b2 = b * b;
  col += BACKDROP_GLOW * (b2 * b2 * b2);
  for (int i = 0; i < SOFTBOX_COUNT; ++i) col += softBox(d, u.boxes[i]);
  return u.env_intensity * col;
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
  const float eps_per_t = u.hit_eps * ray.pixel_angle;
  const float t_floor = intersectFloor(ro, rd);
  const bool floor_visible = t_floor > 0.0f && t_floor < u.max_dist;
  const float tmax = floor_visible ? t_floor : u.max_dist;
  const vec2 span = groupSpan(ro, rd, u);
  const float t0 = dm::max(span.x, 0.0f), t1 = dm::min(span.y, tmax);
  if (t0 < t1) {
    const float t = march(ro, rd, t0, t1, u.max_steps, eps_per_t, 0.0f, u, stats);
    if (t != NO_HIT) {
      const vec3 p = ro + rd * t;
      if (u.hit_mask) return vec3(isObject(p, u) ? HIT_ID_OBJECT : HIT_ID_PEDESTAL);
      const float e = normalEps(ray.pixel_angle, t, u);
      const vec3 n = calcNormal(p, e, u, stats);
      const float bias = surfaceBias(hitEps(eps_per_t, t, u));
      if (isObject(p, u)) {
        const vec3 refl =
            traceReflection(p, n, reflectDir(rd, n), t, eps_per_t, ray.pixel_angle, u, stats);
        return shadeObject(p, n, rd, refl, bias, true, u, stats);
      }
      return shadePedestal(p, n, rd, bias, true, u, stats);
    }
  }
  if (u.hit_mask) return vec3(HIT_ID_NONE);  // the floor is a plane, not marched
  if (floor_visible) {
    const float bias = surfaceBias(hitEps(eps_per_t, t_floor, u));
    return shadeFloor(ro + rd * t_floor, rd, bias, true, u, stats);
  }
  return environment(rd, u);
}

}  // namespace sdfreel::sdf_morph
