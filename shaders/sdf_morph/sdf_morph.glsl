// sdf_morph on the GPU path: the twin of src/scenes/sdf_morph/render.cpp (same functions, same
// names, same order of operations; glm::dot/length -> dm_dot/dm_length). A change there must be
// mirrored here: tests/osmesa compares the two backends' frames.
#include "common/sample_loop.glsl"
#include "common/surface_output.glsl"
#include "sdf_morph/geometry.glsl"
#include "sdf_morph/shading.glsl"

uniform MorphUniforms u_morph;

// ---- studio look (linear Rec.709) ----
const vec3 WALL_LOW = vec3(0.16, 0.155, 0.15);
const vec3 WALL_HIGH = vec3(0.03, 0.032, 0.036);
const vec3 FLOOR_FAR = vec3(0.085, 0.08, 0.075);
const float WALL_GRADIENT_TOP = 0.6;
const float HORIZON_SOFTNESS = 0.04;
const vec3 BACKDROP_DIR = vec3(0.0, 0.148340, 0.988936);
const vec3 BACKDROP_GLOW = vec3(0.22, 0.21, 0.19);
const float SOFTBOX_MIN_COS = 0.05;
const float SOFTBOX_EDGE = 0.02;
const float SOFTBOX_GLOW = 0.04;
const float SOFTBOX_GLOW_FALLOFF = 8.0;

const vec3 PEDESTAL_ALBEDO = vec3(0.5, 0.485, 0.47);
const float PEDESTAL_F0 = 0.03;
const vec3 FLOOR_ALBEDO = vec3(0.2, 0.19, 0.18);
const float FLOOR_FADE_START = 5.0;
const float FLOOR_FADE_END = 20.0;

// ---- marching ----
const float MIN_HIT_EPS = 1e-5;
const float MIN_NORMAL_EPS = 1e-4;
const float NO_HIT = -1.0;
const float MISS_SPAN = 1e30;
const float HIT_ID_NONE = 0.0;
const float HIT_ID_OBJECT = 1.0;
const float HIT_ID_PEDESTAL = 2.0;

const float SHADOW_TMIN = 0.01;
const float SHADOW_HIT_EPS = 1e-3;
const float SHADOW_FIRST_PH = 1e10;
const float SHADOW_MIN_DENOM = 1e-6;

const int AO_TAPS = 5;
const float AO_START = 0.01;
const float AO_SPAN = 0.12;
const float AO_FALLOFF = 0.95;
const float AO_STRENGTH = 3.0;
const float AO_REACH = AO_START + AO_SPAN;

// Declared in sdf_morph/render.h.
vec3 environment(vec3 d, MorphUniforms u);
float softShadow(vec3 ro, vec3 rd, MorphUniforms u, inout RayStats stats);
vec3 calcNormal(vec3 p, float e, MorphUniforms u, inout RayStats stats);

vec2 intersectSphere(vec3 ro, vec3 rd, vec3 center, float radius) {
  precise vec3 oc = ro - center;
  precise float b = dm_dot(oc, rd);
  precise vec3 q = oc - b * rd;
  precise float disc = radius * radius - dm_dot(q, q);
  if (disc < 0.0) { precise vec2 r_ = vec2(MISS_SPAN, -MISS_SPAN); return r_; }
  precise float s = sqrt(disc);
  precise vec2 r_ = vec2(-b - s, -b + s);
  return r_;
}

float intersectFloor(vec3 ro, vec3 rd) {
  if (rd.y == 0.0) return NO_HIT;
  precise float t = -ro.y / rd.y;
  return t > 0.0 ? t : NO_HIT;
}

#define RELAXED_MARCH_PARAMS MorphUniforms u
#define RELAXED_MARCH_MAP(p) mapScene(p, u, stats)
#include "common/relaxed_march.glsl"

float hitEps(float eps_per_t, float t, MorphUniforms u) {
  precise float r_ = u.naive != 0 ? u.hit_eps : dm_max(MIN_HIT_EPS, eps_per_t * t);
  return r_;
}
float normalEps(float pixel_angle, float t, MorphUniforms u) {
  precise float r_ =
      u.naive != 0 ? u.normal_eps : dm_max(MIN_NORMAL_EPS, u.normal_eps * pixel_angle * t);
  return r_;
}
vec2 groupSpan(vec3 ro, vec3 rd, MorphUniforms u) {
  if (u.naive != 0) { precise vec2 r_ = vec2(0.0, u.max_dist); return r_; }
  precise vec2 r_ = intersectSphere(ro, rd, groupBoundCenter(), GROUP_BOUND_RADIUS);
  return r_;
}

vec3 softBox(vec3 d, SoftBox box) {
  precise float c = dm_dot(d, box.dir);
  if (c <= SOFTBOX_MIN_COS) { precise vec3 r_ = vec3(0.0); return r_; }
  precise vec2 uv = vec2(dm_dot(d, box.u), dm_dot(d, box.v)) / c;
  precise float sd = sdRoundRect(uv, box.half_size, box.corner);
  precise float core = 1.0 - dm_smoothstep(-SOFTBOX_EDGE, SOFTBOX_EDGE, sd);
  precise float g = SOFTBOX_GLOW_FALLOFF * dm_max(sd, 0.0);
  precise float glow = SOFTBOX_GLOW / (1.0 + g * g);
  precise vec3 r_ = box.radiance * (core + glow);
  return r_;
}

float ambientOcclusion(vec3 p, vec3 n, MorphUniforms u, inout RayStats stats) {
  precise float occ = 0.0;
  precise float scale = 1.0;
  for (int i = 0; i < AO_TAPS; ++i) {
    precise float h = AO_START + AO_SPAN * float(i) / float(AO_TAPS - 1);
    precise float d = mapScene(p + n * h, u, stats);
    occ += (h - d) * scale;
    scale *= AO_FALLOFF;
  }
  precise float r_ = dm_clamp(1.0 - AO_STRENGTH * occ, 0.0, 1.0);
  return r_;
}

void occlusion(vec3 p, vec3 n, float bias, bool full, MorphUniforms u, inout RayStats stats,
               out float shadow, out float ao) {
  shadow = 1.0;
  ao = 1.0;
  if (!full) return;
  if (dm_dot(n, u.boxes[0].dir) > 0.0) shadow = softShadow(p + n * bias, u.boxes[0].dir, u, stats);
  if (u.naive != 0 || dm_length(p - groupBoundCenter()) < GROUP_BOUND_RADIUS + AO_REACH)
    ao = ambientOcclusion(p, n, u, stats);
}

vec3 shadeFloor(vec3 p, vec3 rd, float bias, bool full, MorphUniforms u, inout RayStats stats) {
  precise vec3 n = vec3(0.0, 1.0, 0.0);
  precise float shadow, ao;
  occlusion(p, n, bias, full, u, stats, shadow, ao);
  precise vec3 col = diffuseLight(FLOOR_ALBEDO, n, shadow, ao, u);
  precise float fade = dm_smoothstep(FLOOR_FADE_START, FLOOR_FADE_END, dm_length(vec2(p.x, p.z)));
  precise vec3 r_ = dm_mix(col, environment(rd, u), fade);
  return r_;
}

vec3 shadePedestal(vec3 p, vec3 n, vec3 rd, float bias, bool full, MorphUniforms u,
                   inout RayStats stats) {
  precise float shadow, ao;
  occlusion(p, n, bias, full, u, stats, shadow, ao);
  precise vec3 diffuse = diffuseLight(PEDESTAL_ALBEDO, n, shadow, ao, u);
  precise float f = schlick(dm_dot(n, -rd), PEDESTAL_F0);
  precise vec3 r_ = dm_mix(diffuse, environment(reflectDir(rd, n), u) * ao, f);
  return r_;
}

vec3 shadeObject(vec3 p, vec3 n, vec3 rd, vec3 reflection, float bias, bool full, MorphUniforms u,
                 inout RayStats stats) {
  precise float shadow, ao;
  occlusion(p, n, bias, full, u, stats, shadow, ao);
  precise vec3 diffuse = diffuseLight(u.base_color, n, shadow, ao, u);
  precise float f = schlick(dm_dot(n, -rd), u.reflectivity);
  precise vec3 r_ = dm_mix(diffuse, reflection, f);
  return r_;
}

vec3 traceReflection(vec3 p, vec3 n, vec3 r, float t_before, float eps_per_t, float pixel_angle,
                     MorphUniforms u, inout RayStats stats) {
  precise vec3 ro = p + n * surfaceBias(hitEps(eps_per_t, t_before, u));
  precise float t_floor = intersectFloor(ro, r);
  precise float tmax = t_floor > 0.0 ? dm_min(t_floor, u.max_dist) : u.max_dist;
  precise vec2 span = groupSpan(ro, r, u);
  precise float t0 = dm_max(span.x, 0.0), t1 = dm_min(span.y, tmax);
  if (t0 < t1) {
    precise float t = march(ro, r, t0, t1, u.reflect_steps, eps_per_t, t_before, u, stats);
    if (t != NO_HIT) {
      precise vec3 q = ro + r * t;
      precise float e = normalEps(pixel_angle, t_before + t, u);
      precise vec3 nq = calcNormal(q, e, u, stats);
      if (isObject(q, u)) {
        precise vec3 r_ =
            shadeObject(q, nq, r, environment(reflectDir(r, nq), u), 0.0, false, u, stats);
        return r_;
      }
      precise vec3 r_ = shadePedestal(q, nq, r, 0.0, false, u, stats);
      return r_;
    }
  }
  if (t_floor > 0.0 && t_floor < u.max_dist) {
    precise vec3 r_ = shadeFloor(ro + r * t_floor, r, 0.0, false, u, stats);
    return r_;
  }
  precise vec3 r_ = environment(r, u);
  return r_;
}

vec3 environment(vec3 d, MorphUniforms u) {
  precise vec3 wall = dm_mix(WALL_LOW, WALL_HIGH, dm_smoothstep(0.0, WALL_GRADIENT_TOP, d.y));
  precise vec3 col =
      dm_mix(FLOOR_FAR, wall, dm_smoothstep(-HORIZON_SOFTNESS, HORIZON_SOFTNESS, d.y));
  precise float b = dm_max(dm_dot(d, BACKDROP_DIR), 0.0);
  precise float b2 = b * b;
  col += BACKDROP_GLOW * (b2 * b2 * b2);
  for (int i = 0; i < SOFTBOX_COUNT; ++i) col += softBox(d, u.boxes[i]);
  precise vec3 r_ = u.env_intensity * col;
  return r_;
}

float softShadow(vec3 ro, vec3 rd, MorphUniforms u, inout RayStats stats) {
  precise vec2 span = groupSpan(ro, rd, u);
  if (span.y <= 0.0) return 1.0;
  precise float t = dm_max(SHADOW_TMIN, span.x);
  precise float res = 1.0;
  precise float ph = SHADOW_FIRST_PH;
  for (int i = 0; i < u.shadow_steps && t < span.y; ++i) {
    stats.steps += 1u;
    stats.sdf_evals += 1u;
    precise float margin = dm_max(OBJECT_BOUND_MARGIN, t / u.shadow_k);
    bool exact;
    precise float h = mapSceneBounded(ro + rd * t, u, margin, exact);
    if (h < SHADOW_HIT_EPS) return 0.0;
    if (exact) {
      precise float y = h * h / (2.0 * ph);
      precise float d = sqrt(dm_max(h * h - y * y, 0.0));
      res = dm_min(res, u.shadow_k * d / dm_max(t - y, SHADOW_MIN_DENOM));
      ph = h;
    } else {
      ph = SHADOW_FIRST_PH;
    }
    t += h;
  }
  res = dm_clamp(res, 0.0, 1.0);
  precise float r_ = res * res * (3.0 - 2.0 * res);
  return r_;
}

vec3 calcNormal(vec3 p, float e, MorphUniforms u, inout RayStats stats) {
  const vec3 a = vec3(1.0, -1.0, -1.0), b = vec3(-1.0, -1.0, 1.0), c = vec3(-1.0, 1.0, -1.0),
             d = vec3(1.0, 1.0, 1.0);
  return safe_normalize(a * mapScene(p + a * e, u, stats) + b * mapScene(p + b * e, u, stats) +
                        c * mapScene(p + c * e, u, stats) + d * mapScene(p + d * e, u, stats));
}

vec3 sceneRadiance(Ray ray, MorphUniforms u, inout RayStats stats) {
  precise vec3 ro = ray.origin, rd = ray.dir;
  precise float eps_per_t = u.hit_eps * ray.pixel_angle;
  precise float t_floor = intersectFloor(ro, rd);
  bool floor_visible = t_floor > 0.0 && t_floor < u.max_dist;
  precise float tmax = floor_visible ? t_floor : u.max_dist;
  precise vec2 span = groupSpan(ro, rd, u);
  precise float t0 = dm_max(span.x, 0.0), t1 = dm_min(span.y, tmax);
  if (t0 < t1) {
    precise float t = march(ro, rd, t0, t1, u.max_steps, eps_per_t, 0.0, u, stats);
    if (t != NO_HIT) {
      precise vec3 p = ro + rd * t;
      if (u.hit_mask != 0) {
        precise vec3 r_ = vec3(isObject(p, u) ? HIT_ID_OBJECT : HIT_ID_PEDESTAL);
        return r_;
      }
      precise float e = normalEps(ray.pixel_angle, t, u);
      precise vec3 n = calcNormal(p, e, u, stats);
      if (u.surface != SURFACE_COLOUR) { precise vec3 r_ = surfaceOutput(u.surface, t, n); return r_; }
      precise float bias = surfaceBias(hitEps(eps_per_t, t, u));
      if (isObject(p, u)) {
        precise vec3 refl =
            traceReflection(p, n, reflectDir(rd, n), t, eps_per_t, ray.pixel_angle, u, stats);
        precise vec3 r_ = shadeObject(p, n, rd, refl, bias, true, u, stats);
        return r_;
      }
      precise vec3 r_ = shadePedestal(p, n, rd, bias, true, u, stats);
      return r_;
    }
  }
  if (u.hit_mask != 0) { precise vec3 r_ = vec3(HIT_ID_NONE); return r_; }
  if (u.surface != SURFACE_COLOUR) {
    precise vec3 r_ = floor_visible ? surfaceOutput(u.surface, t_floor, vec3(0.0, 1.0, 0.0))
                                    : noSurface(u.surface);
    return r_;
  }
  if (floor_visible) {
    precise float bias = surfaceBias(hitEps(eps_per_t, t_floor, u));
    precise vec3 r_ = shadeFloor(ro + rd * t_floor, rd, bias, true, u, stats);
    return r_;
  }
  precise vec3 r_ = environment(rd, u);
  return r_;
}

vec3 radiance(Ray ray, inout RayStats stats) {
  precise vec3 r_ = sceneRadiance(ray, u_morph, stats);
  return r_;
}
