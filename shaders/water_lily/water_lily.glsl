// water_lily on the GPU path: the twin of src/scenes/water_lily/render.cpp (same functions, same
// names, same order of operations; glm::dot/length -> dm_dot/dm_length). A change there must be
// mirrored here: tests/osmesa compares the two backends' frames.
#include "common/sample_loop.glsl"
#include "common/surface_output.glsl"
#include "common/noise.glsl"
#include "water_lily/geometry.glsl"
#include "water_lily/look.glsl"
#include "water_lily/droplets.glsl"

uniform LilyUniforms u_lily;

// ---- marching ----
const float MIN_HIT_EPS = 1e-5;
const float MIN_NORMAL_EPS = 1e-4;
const float MIN_SURFACE_BIAS = 2e-3;
const float SURFACE_BIAS_FACTOR = 2.0;
const float NO_HIT = -1.0;
const float BOUND_MARGIN = 0.05;
const float HIT_ID_NONE = 0.0;
const float HIT_ID_FLOWER = 1.0;
const float HIT_ID_LEAF = 2.0;

const float SHADOW_TMIN = 0.01;
const float SHADOW_HIT_EPS = 1e-4;
const float SHADOW_FIRST_PH = 1e10;
const float SHADOW_MIN_DENOM = 1e-6;
const float SHADOW_MIN_STEP = 1e-4;
const float FILL_SHADOW_SOFTNESS = 0.35;
const float REFLECT_MAX_DIST = 14.0;
const float REFLECT_HIT_SCALE = 4.0;

vec3 skyColor(vec3 d, LilyUniforms u);

vec2 axisSpan(float o, float d, float lo, float hi) {
  if (d == 0.0) {
    bool inside = o > lo && o < hi;
    return inside ? vec2(-BIG_DISTANCE, BIG_DISTANCE) : vec2(BIG_DISTANCE, -BIG_DISTANCE);
  }
  precise float ta = (lo - o) / d;
  precise float tb = (hi - o) / d;
  return vec2(dm_min(ta, tb), dm_max(ta, tb));
}

vec2 slabSpan(vec3 ro, vec3 rd) {
  precise vec2 sx = axisSpan(ro.x, rd.x, FIELD_MIN.x, FIELD_MAX.x);
  precise vec2 sy = axisSpan(ro.y, rd.y, FIELD_MIN.y, FIELD_MAX.y);
  precise vec2 sz = axisSpan(ro.z, rd.z, FIELD_MIN.z, FIELD_MAX.z);
  precise float enter = dm_max(dm_max(sx.x, sy.x), dm_max(sz.x, 0.0));
  precise float exit = dm_min(dm_min(sx.y, sy.y), sz.y);
  return vec2(enter, exit);
}

float intersectWater(vec3 ro, vec3 rd) {
  if (!(rd.y < 0.0) || ro.y < 0.0) return NO_HIT;
  return -ro.y / rd.y;
}

float hitEps(float eps_per_t, float t, LilyUniforms u) {
  return u.naive != 0 ? u.hit_eps : dm_max(MIN_HIT_EPS, eps_per_t * t);
}
float normalEps(float pixel_angle, float t, LilyUniforms u) {
  return u.naive != 0 ? u.normal_eps : dm_max(MIN_NORMAL_EPS, u.normal_eps * pixel_angle * t);
}
float surfaceBias(float eps) { return dm_max(MIN_SURFACE_BIAS, SURFACE_BIAS_FACTOR * eps); }

float mapScene(vec3 p, bool leaves, LilyUniforms u, inout RayStats stats) {
  stats.sdf_evals += 1u;
  return mapNearest(p, u, BOUND_MARGIN, leaves).d;
}

#define RELAXED_MARCH_PARAMS bool leaves, LilyUniforms u
#define RELAXED_MARCH_MAP(p) mapScene(p, leaves, u, stats)
#include "common/relaxed_march.glsl"

vec3 calcNormal(vec3 p, float e, bool leaves, LilyUniforms u, inout RayStats stats) {
  const vec3 a = vec3(1.0, -1.0, -1.0), b = vec3(-1.0, -1.0, 1.0), c = vec3(-1.0, 1.0, -1.0),
             d = vec3(1.0, 1.0, 1.0);
  precise float da = mapScene(p + a * e, leaves, u, stats);
  precise float db = mapScene(p + b * e, leaves, u, stats);
  precise float dc = mapScene(p + c * e, leaves, u, stats);
  precise float dd = mapScene(p + d * e, leaves, u, stats);
  return safe_normalize(a * da + b * db + c * dc + d * dd);
}

vec3 reflectDir(vec3 d, vec3 n) { return d - 2.0 * dm_dot(n, d) * n; }

float schlick(float cos_theta, float f0) {
  precise float x = 1.0 - dm_clamp(cos_theta, 0.0, 1.0);
  precise float x2 = x * x;
  return f0 + (1.0 - f0) * (x2 * x2 * x);
}

float softShadow(vec3 ro, vec3 ld, float k, int steps, LilyUniforms u, inout RayStats stats) {
  precise vec2 span = slabSpan(ro, ld);
  precise float tmax = u.naive != 0 ? u.max_dist : span.y;
  precise float t = dm_max(SHADOW_TMIN, u.naive != 0 ? 0.0 : span.x);
  precise float res = 1.0;
  precise float ph = SHADOW_FIRST_PH;
  precise float step = 0.0;
  for (int i = 0; i < steps && t < tmax; ++i) {
    stats.steps += 1u;
    stats.sdf_evals += 1u;
    Nearest n = mapNearest(ro + ld * t, u, dm_max(BOUND_MARGIN, t / k), true);
    precise float h = n.est;
    if (h < SHADOW_HIT_EPS) return 0.0;
    if (n.exact) {
      precise float y = 0.0;
      if (abs(h - ph) < step)
        y = dm_max((h * h - ph * ph + step * step) / (2.0 * step), 0.0);
      precise float d = sqrt(dm_max(h * h - y * y, 0.0));
      res = dm_min(res, k * d / dm_max(t - y, SHADOW_MIN_DENOM));
      ph = h;
    } else {
      ph = SHADOW_FIRST_PH;
    }
    step = dm_max(n.d, SHADOW_MIN_STEP);
    t += step;
  }
  res = dm_clamp(res, 0.0, 1.0);
  return res * res * (3.0 - 2.0 * res);
}

// ---- materials ----

vec3 petalAlbedo(int f, float along, int layer) {
  precise vec3 tip = (f % 2 == 0) ? PETAL_WHITE : PETAL_PINK_TIP;
  precise float pink =
      dm_clamp(1.0 - along * PETAL_GRADIENT + float(layer) * PETAL_LAYER_PINK, 0.0, 1.0);
  return dm_mix(tip, PETAL_BASE, pink * pink);
}

vec3 leafAlbedo(int i, vec3 q) {
  precise float radius = LEAVES[i].radius;
  uint seed = LEAF_SEED + uint(i);
  precise vec3 base = dm_mix(LEAF_GREEN_A, LEAF_GREEN_B, hash_to_unit(pcg_hash(seed)));
  precise vec2 w = worley(vec2(q.x, q.z) * LEAF_CELL_FREQUENCY, seed);
  precise float border = 1.0 - dm_smoothstep(0.0, LEAF_BORDER_WIDTH, w.y - w.x);
  precise vec3 col = dm_mix(base * (0.85 + 0.3 * w.x), LEAF_VEIN, border * LEAF_BORDER_WEIGHT);
  precise float rho = sqrt(q.x * q.x + q.z * q.z);
  precise float angle = dm_atan2(q.z, q.x);
  precise float vein = 0.5 + 0.5 * dm_cos(angle * LEAF_VEIN_COUNT);
  col = col * (1.0 - LEAF_VEIN_DEPTH * vein * dm_smoothstep(0.1, 0.6, rho / radius));
  return dm_mix(col, LEAF_RIM, dm_smoothstep(0.9, 1.0, rho / radius) * LEAF_RIM_WEIGHT);
}

struct Surface {
  vec3 albedo;
  float translucent;
  float shininess;
  float specular;
  vec3 tilt;
};

// addDroplet() of src/scenes/water_lily/render.cpp: a water drop's dome, ring, caustic and
// highlight.
Surface addDroplet(Surface s, Droplet d, LilyUniforms u) {
  if (!(d.cover > 0.0)) return s;
  precise vec2 o = d.offset;
  precise float r = sqrt(o.x * o.x + o.y * o.y);
  s.tilt = vec3(o.x, 0.0, o.y) * (DROP_SLOPE * d.cover);
  precise float ring = dm_smoothstep(DROP_RING, 1.0, r);
  precise float caustic = dm_max(-(o.x * u.sun_dir.x + o.y * u.sun_dir.z), 0.0) * (1.0 - r);
  precise vec3 under = s.albedo * (1.0 - DROP_RING_DARK * ring + DROP_CAUSTIC * caustic);
  s.albedo = dm_mix(s.albedo, under, d.cover);
  s.shininess = DROP_SHININESS;
  s.specular = dm_mix(s.specular, DROP_SPECULAR, d.cover);
  return s;
}

Surface surfaceAt(vec3 p, vec3 n, bool leaves, LilyUniforms u) {
  Nearest near = mapNearest(p, u, BOUND_MARGIN, leaves);
  if (near.flower >= 0) {
    precise vec3 q = toFlower(p, near.flower);
    precise float center = flowerCenter(q);
    FlowerPlacement fl = FLOWERS[near.flower];
    if (center < CENTER_COLOR_REACH)
      return Surface(dm_mix(CENTER_DEEP, CENTER_YELLOW,
                            dm_smoothstep(0.0, CENTER_RADIUS, q.y - CENTER_Y + CENTER_RADIUS)),
                     0.0, 0.0, 0.0, vec3(0.0));
    int layer = 0;
    precise float best = petalLayer(q, 0, fl.turn, u.curl[near.flower], u).x;
    for (int l = 1; l < PETAL_LAYERS; ++l) {
      precise float d = petalLayer(q, l, fl.turn, u.curl[near.flower], u).x;
      if (d < best) {
        best = d;
        layer = l;
      }
    }
    precise float along = sqrt(q.x * q.x + q.z * q.z + q.y * q.y) / PETAL_TIP_REACH;
    Surface s = Surface(petalAlbedo(near.flower, along, layer), 1.0, 0.0, 0.0, vec3(0.0));
    precise vec2 plan = vec2(p.x - fl.xz.x, p.z - fl.xz.y);
    return addDroplet(
        s, dropletAt(plan, DROP_SEED + uint(near.flower), DROP_SHARE_PETAL * u.droplets, n.y), u);
  }
  int leaf = near.leaf >= 0 ? near.leaf : 0;
  Surface s =
      Surface(leafAlbedo(leaf, toLeaf(p, leaf, u)), 0.0, LEAF_SHININESS, LEAF_SPECULAR, vec3(0.0));
  precise vec2 c = leafCenter(leaf, u);
  uint seed = DROP_SEED + uint(FLOWER_COUNT + leaf);
  return addDroplet(
      s, dropletAt(vec2(p.x - c.x, p.z - c.y), seed, DROP_SHARE_PAD * u.droplets, n.y), u);
}

vec3 lightSurface(Surface s, vec3 surface_n, vec3 rd, float sun_shadow, float fill_shadow,
                  LilyUniforms u) {
  precise vec3 n = safe_normalize(surface_n + s.tilt);
  precise float ndl = dm_max(dm_dot(n, u.sun_dir), 0.0);
  precise float fill = dm_max(dm_dot(n, u.fill_dir), 0.0);
  precise float sky = 0.6 + 0.4 * n.y;
  precise vec3 light = u.sun_color * (ndl * sun_shadow) + FILL_COLOR * (fill * fill_shadow) +
                       AMBIENT_SKY * (sky * (0.5 + 0.5 * fill_shadow));
  precise vec3 col = s.albedo * light;
  if (s.translucent > 0.0) {
    precise float back = dm_max(-dm_dot(n, u.sun_dir), 0.0);
    precise float towards = 0.5 + 0.5 * dm_max(dm_dot(rd, u.sun_dir), 0.0);
    col = col + s.albedo * PETAL_TRANSMIT * u.sun_color *
                    (u.translucency * s.translucent * back * towards * sun_shadow);
  }
  if (s.shininess > 0.0) {
    precise float h = dm_max(dm_dot(reflectDir(rd, n), u.sun_dir), 0.0);
    col = col + u.sun_color * (s.specular * dm_pow(h, s.shininess) * sun_shadow);
  }
  return col;
}

// throughPetal() of src/scenes/water_lily/render.h: out of a backlit petal, along -n.
const int PETAL_EXIT_STEPS = 8;
vec3 throughPetal(vec3 p, vec3 n, float bias, LilyUniforms u, inout RayStats stats) {
  precise vec3 q = p - n * bias;
  for (int i = 0; i < PETAL_EXIT_STEPS; ++i) {
    precise float d = mapScene(q, false, u, stats);
    if (d > bias) break;
    q = q - n * (bias - d);
  }
  return q;
}

vec3 shadeSurface(vec3 p, vec3 n, vec3 rd, float bias, LilyUniforms u, inout RayStats stats) {
  Surface s = surfaceAt(p, n, true, u);
  precise vec3 o = p + n * bias;
  bool sun_side = dm_dot(n, u.sun_dir) > 0.0 || s.translucent > 0.0;
  precise vec3 os = dm_dot(n, u.sun_dir) > 0.0 ? o : throughPetal(p, n, bias, u, stats);
  precise float sun =
      sun_side ? softShadow(os, u.sun_dir, u.shadow_k, u.shadow_steps, u, stats) : 1.0;
  precise float fill =
      softShadow(o, u.fill_dir, u.shadow_k * FILL_SHADOW_SOFTNESS, u.shadow_steps / 2, u, stats);
  return lightSurface(s, n, rd, sun, fill, u);
}

float waterHeight(float x, float z, LilyUniforms u) {
  precise float h = fbm(vec3(x * WATER_FREQUENCY, z * WATER_FREQUENCY, u.water_time_a),
                        WATER_OCTAVES, WATER_SEED);
  if (!(u.water_blend > 0.0)) return h;
  precise float hb = fbm(vec3(x * WATER_FREQUENCY, z * WATER_FREQUENCY, u.water_time_b),
                         WATER_OCTAVES, WATER_SEED);
  return dm_mix(h, hb, u.water_blend);
}

float submergedLeaf(vec3 w, vec3 rd, out vec3 col) {
  col = vec3(0.0);
  precise vec3 down = safe_normalize(vec3(rd.x * REFRACT_BEND, rd.y, rd.z * REFRACT_BEND));
  precise float t = SUBMERGED_DEPTH / -down.y;
  precise vec3 s = w + down * t;
  precise float cover = 0.0;
  for (int i = 0; i < SUBMERGED_COUNT; ++i) {
    LeafPlacement leaf = SUBMERGED[i];
    precise float dx = s.x - leaf.xz.x, dz = s.z - leaf.xz.y;
    precise float cs = dm_cos(leaf.notch_angle), sn = dm_sin(leaf.notch_angle);
    precise vec3 q = vec3(cs * dx + sn * dz, 0.0, cs * dz - sn * dx);
    precise float disc = sqrt(q.x * q.x + q.z * q.z) - leaf.radius;
    precise float d = opSubtraction(leafNotch(q, leaf.radius), disc);
    precise float c = 1.0 - dm_smoothstep(-SUBMERGED_EDGE, SUBMERGED_EDGE, d);
    if (c > cover) {
      cover = c;
      col = SUBMERGED_GREEN * (0.8 + 0.4 * hash_to_unit(pcg_hash(LEAF_SEED + 100u + uint(i))));
    }
  }
  return cover;
}

// reflectedLily() of src/scenes/water_lily/render.cpp: the seed's "lighter color that fits the
// scene", the lily's colour lit as its sunlit side is.
vec3 reflectedLily(Surface s, LilyUniforms u) {
  return s.albedo * (u.sun_color * u.sun_dir.y + AMBIENT_SKY);
}

vec3 traceReflection(vec3 w, vec3 r, float t_before, float eps_per_t, LilyUniforms u,
                     inout RayStats stats) {
  precise vec3 sky = skyColor(r, u);
  precise vec2 span = slabSpan(w, r);
  precise float t1 = dm_min(span.y, u.naive != 0 ? u.max_dist : REFLECT_MAX_DIST);
  if (!(span.x < t1)) return sky;
  precise float t = march(w, r, span.x, t1, u.reflect_steps, eps_per_t * REFLECT_HIT_SCALE,
                          t_before, false, u, stats);
  if (t == NO_HIT) return sky;
  precise vec3 q = w + r * t;
  precise vec3 col = reflectedLily(surfaceAt(q, vec3(0.0), false, u), u);
  return dm_mix(sky, col, dm_exp(-REFLECT_FALLOFF * t));
}

vec3 waterNormal(float x, float z, float dist, LilyUniforms u);

vec3 shadeWater(vec3 ro, vec3 rd, float t, float eps_per_t, LilyUniforms u,
                inout RayStats stats) {
  precise vec3 w = ro + rd * t;
  precise vec3 n = waterNormal(w.x, w.z, t, u);
  precise float fresnel = schlick(-dm_dot(n, rd), WATER_F0);
  precise vec3 r = reflectDir(rd, n);
  r.y = abs(r.y);
  precise float bias = surfaceBias(hitEps(eps_per_t, t, u));
  precise vec3 wo = vec3(w.x, bias, w.z);
  precise vec3 mirror = traceReflection(wo, r, t, eps_per_t, u, stats);
  precise float sun = softShadow(wo, u.sun_dir, u.shadow_k, u.shadow_steps, u, stats);
  precise float fill =
      softShadow(wo, u.fill_dir, u.shadow_k * FILL_SHADOW_SOFTNESS, u.shadow_steps / 2, u, stats);
  precise vec3 body = WATER_DEEP * (WATER_SUN_SHARE * sun + (1.0 - WATER_SUN_SHARE) * fill);
  precise vec3 leaf_col;
  precise float cover = submergedLeaf(w, rd, leaf_col);
  precise vec3 leaf_lit = leaf_col * (u.sun_color * (u.sun_dir.y * sun) + AMBIENT_SKY * fill);
  body = dm_mix(body, leaf_lit * SUBMERGED_TRANSMIT, cover);
  precise float glint = dm_pow(dm_max(dm_dot(r, u.sun_dir), 0.0), SUN_GLINT_POWER);
  precise vec3 mirror_lit = mirror + u.sun_color * (SUN_GLINT * glint * sun);
  return dm_mix(body, mirror_lit, fresnel);
}

vec3 applyFog(vec3 col, float t, LilyUniforms u) {
  precise float fog = dm_smoothstep(FOG_START_SHARE * u.fog_distance, u.fog_distance, t);
  return dm_mix(col, FOG_COLOR, fog);
}

vec3 underwater(vec3 rd) { return UNDERWATER * (0.4 + 0.6 * dm_max(rd.y, 0.0)); }

vec3 skyColor(vec3 d, LilyUniforms u) {
  precise float y = dm_max(d.y, 0.0);
  precise vec3 col = dm_mix(SKY_HORIZON, SKY_ZENITH, sqrt(y));
  precise float lift = 1.0 / (y + CLOUD_LIFT);
  precise vec2 c = vec2(d.x * lift * CLOUD_SCALE + u.cloud_shift, d.z * lift * CLOUD_SCALE);
  precise float cloud = fbm(c, CLOUD_OCTAVES, CLOUD_SEED);
  precise float glow = dm_smoothstep(CLOUD_LOW, CLOUD_HIGH, cloud) * dm_smoothstep(0.0, 0.25, y);
  col = dm_mix(col, CLOUD_COLOR, glow * CLOUD_WEIGHT);
  precise float s = dm_max(dm_dot(d, u.sun_dir), 0.0);
  precise float s2 = s * s;
  precise float s4 = s2 * s2;
  return col + u.sun_color * (SUN_GLOW * s4 * s4 * (0.6 + 0.8 * cloud));
}

vec3 waterNormal(float x, float z, float dist, LilyUniforms u) {
  precise float bump =
      u.water_bump * WATER_BUMP * (1.0 - dm_smoothstep(WATER_CALM_NEAR, WATER_CALM_FAR, dist));
  if (!(bump > 0.0)) return vec3(0.0, 1.0, 0.0);
  precise float h = waterHeight(x, z, u);
  precise float hx = waterHeight(x + WATER_DELTA, z, u);
  precise float hz = waterHeight(x, z + WATER_DELTA, u);
  precise float gx = (hx - h) / WATER_DELTA, gz = (hz - h) / WATER_DELTA;
  return safe_normalize(vec3(-gx * bump, 1.0, -gz * bump));
}

vec3 grade(vec3 c, vec3 rd, LilyUniforms u) {
  precise vec3 col = dm_clamp(c, 0.0, 1.0);
  col = dm_mix(col, col * col * (vec3(3.0) - 2.0 * col), u.contrast);
  precise float grey = dm_dot(col, vec3(SATURATION_GREY));
  col = dm_mix(vec3(grey), col, u.saturation);
  precise float f = dm_dot(rd, u.cam_forward);
  precise float sx = dm_dot(rd, u.cam_right) / f * u.inv_tan_half_fov * u.inv_aspect;
  precise float sy = dm_dot(rd, u.cam_up) / f * u.inv_tan_half_fov;
  precise float r2 = sx * sx + sy * sy;
  precise float falloff = 1.0 + u.vignette * u.vignette * r2;  // the seed's vignette
  return col * (1.0 / (falloff * falloff));
}

vec3 sceneRadiance(Ray ray, LilyUniforms u, inout RayStats stats) {
  precise vec3 ro = ray.origin, rd = ray.dir;
  precise float eps_per_t = u.hit_eps * ray.pixel_angle;
  precise float t_water = intersectWater(ro, rd);
  bool water = t_water != NO_HIT && t_water < u.max_dist;
  precise vec2 span = u.naive != 0 ? vec2(0.0, u.max_dist) : slabSpan(ro, rd);
  precise float t1 = dm_min(span.y, water ? t_water : u.max_dist);
  precise float t = NO_HIT;
  if (span.x < t1) t = march(ro, rd, span.x, t1, u.max_steps, eps_per_t, 0.0, true, u, stats);
  if (u.hit_mask != 0) {
    if (t == NO_HIT) return vec3(HIT_ID_NONE);
    return vec3(mapNearest(ro + rd * t, u, BOUND_MARGIN, true).flower >= 0 ? HIT_ID_FLOWER
                                                                      : HIT_ID_LEAF);
  }
  if (u.surface != SURFACE_COLOUR) {  // the depth and normal passes: a lily, a pad or the water
    if (t != NO_HIT) {
      precise vec3 p = ro + rd * t;
      precise vec3 n = calcNormal(p, normalEps(ray.pixel_angle, t, u), true, u, stats);
      precise vec3 r_ = surfaceOutput(u.surface, t, n);
      return r_;
    }
    if (water) {
      precise vec3 w = ro + rd * t_water;
      precise vec3 r_ = surfaceOutput(u.surface, t_water, waterNormal(w.x, w.z, t_water, u));
      return r_;
    }
    precise vec3 r_ = noSurface(u.surface);
    return r_;
  }
  precise vec3 col;
  precise float dist;
  if (t != NO_HIT) {
    precise vec3 p = ro + rd * t;
    precise vec3 n = calcNormal(p, normalEps(ray.pixel_angle, t, u), true, u, stats);
    col = shadeSurface(p, n, rd, surfaceBias(hitEps(eps_per_t, t, u)), u, stats);
    dist = t;
  } else if (water) {
    col = shadeWater(ro, rd, t_water, eps_per_t, u, stats);
    dist = t_water;
  } else if (ro.y < 0.0) {
    return grade(underwater(rd), rd, u);
  } else {
    return grade(skyColor(rd, u), rd, u);
  }
  return grade(applyFog(col, dist, u), rd, u);
}

vec3 radiance(Ray ray, inout RayStats stats) { return sceneRadiance(ray, u_lily, stats); }
