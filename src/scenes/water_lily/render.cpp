#include "scenes/water_lily/render.h"

#include "scenes/common/relaxed_march.h"
#include "scenes/common/surface_output.h"
#include "scenes/water_lily/droplets.h"
#include "scenes/water_lily/geometry.h"
#include "scenes/water_lily/look.h"
#include "scenes/water_lily/shadow.h"
#include "sdf/det_math.h"
#include "sdf/noise.h"
#include "sdf/sdf.h"

namespace sdfreel::water_lily {
namespace {

using glm::vec2;
using glm::vec3;

// ---- marching ----
constexpr float MIN_NORMAL_EPS = 1e-4f;
constexpr float MIN_SURFACE_BIAS = 2e-3f;
constexpr float SURFACE_BIAS_FACTOR = 2.0f;
constexpr float HIT_ID_NONE = 0.0f;
constexpr float HIT_ID_FLOWER = 1.0f;
constexpr float HIT_ID_LEAF = 2.0f;

constexpr float REFLECT_MAX_DIST = 14.0f;  // reflections of lilies farther away fade out anyway
// Reflections are seen through the bumped water, blurred: a coarser hit threshold lets a
// reflected ray that creeps over a pad's rim stop (hard case horizon_grazing: out of steps).
constexpr float REFLECT_HIT_SCALE = 4.0f;

// Where the ray is inside lo < x < hi along one axis: (enter, exit) from -inf to inf; a ray
// parallel to the slab is inside or outside as a whole.
vec2 axisSpan(float o, float d, float lo, float hi) {
  if (d == 0.0f) {
    const bool inside = o > lo && o < hi;
    return inside ? vec2(-BIG_DISTANCE, BIG_DISTANCE) : vec2(BIG_DISTANCE, -BIG_DISTANCE);
  }
  const float ta = (lo - o) / d;
  const float tb = (hi - o) / d;
  return vec2(dm::min(ta, tb), dm::max(ta, tb));
}

// Where a ray is inside the field box (FIELD_MIN, FIELD_MAX) from t = 0: (enter, exit), empty
// (enter >= exit) when it never is. Rays far over the pond leave it early (hard case
// horizon_grazing: a level ray would otherwise creep over the water to max_dist).
vec2 slabSpan(const vec3& ro, const vec3& rd) {
  const vec2 sx = axisSpan(ro.x, rd.x, FIELD_MIN.x, FIELD_MAX.x);
  const vec2 sy = axisSpan(ro.y, rd.y, FIELD_MIN.y, FIELD_MAX.y);
  const vec2 sz = axisSpan(ro.z, rd.z, FIELD_MIN.z, FIELD_MAX.z);
  const float enter = dm::max(dm::max(sx.x, sy.x), dm::max(sz.x, 0.0f));
  const float exit = dm::min(dm::min(sx.y, sy.y), sz.y);
  return vec2(enter, exit);
}

// Distance to the water plane along the ray, or NO_HIT (also for an eye under the water).
float intersectWater(const vec3& ro, const vec3& rd) {
  if (!(rd.y < 0.0f) || ro.y < 0.0f) return NO_HIT;
  return -ro.y / rd.y;
}

float hitEps(float eps_per_t, float t, const LilyUniforms& u) {
  return u.naive ? u.hit_eps : dm::max(MIN_HIT_EPS, eps_per_t * t);
}
float normalEps(float pixel_angle, float t, const LilyUniforms& u) {
  return u.naive ? u.normal_eps : dm::max(MIN_NORMAL_EPS, u.normal_eps * pixel_angle * t);
}
float surfaceBias(float eps) {
  return dm::max(MIN_SURFACE_BIAS, SURFACE_BIAS_FACTOR * eps);
}

// Sphere tracing with over-relaxation (Keinert et al. 2014), as sdf_morph's march: a step that
// jumped past a surface falls back to a plain step; only a plain step may leave at tmax. The
// threshold grows with the path length eps_per_t * (t_before + t); a ray out of steps counts as
// a hit where it stopped (stats.capped). Returns t or NO_HIT.
float march(const vec3& ro, const vec3& rd, float tmin, float tmax, int max_steps, float eps_per_t,
            float t_before, bool leaves, const LilyUniforms& u, RayStats& stats) {
  const RelaxedMarchSettings s{max_steps, u.naive, u.step_factor, u.hit_eps, MIN_HIT_EPS, NO_HIT};
  return relaxed_march([&](const vec3& p) { return mapScene(p, leaves, u, stats); }, ro, rd, tmin,
                       tmax, eps_per_t, t_before, s, stats);
}

vec3 calcNormal(const vec3& p, float e, bool leaves, const LilyUniforms& u, RayStats& stats) {
  const vec3 a(1.0f, -1.0f, -1.0f), b(-1.0f, -1.0f, 1.0f), c(-1.0f, 1.0f, -1.0f),
      d(1.0f, 1.0f, 1.0f);
  return safe_normalize(
      a * mapScene(p + a * e, leaves, u, stats) + b * mapScene(p + b * e, leaves, u, stats) +
      c * mapScene(p + c * e, leaves, u, stats) + d * mapScene(p + d * e, leaves, u, stats));
}

vec3 reflectDir(const vec3& d, const vec3& n) {
  return d - 2.0f * glm::dot(n, d) * n;
}

float schlick(float cos_theta, float f0) {
  const float x = 1.0f - dm::clamp(cos_theta, 0.0f, 1.0f);
  const float x2 = x * x;
  return f0 + (1.0f - f0) * (x2 * x2 * x);
}

// ---- materials ----

// Petal colour: white tips over a pink base (white and pink flowers alternate); the inner layers
// are pinker. `along` is 0 at the flower axis, 1 at the outer petals' tips.
vec3 petalAlbedo(int f, float along, int layer) {
  const vec3 tip = (f % 2 == 0) ? PETAL_WHITE : PETAL_PINK_TIP;
  const float pink =
      dm::clamp(1.0f - along * PETAL_GRADIENT + float(layer) * PETAL_LAYER_PINK, 0.0f, 1.0f);
  return dm::mix(tip, PETAL_BASE, pink * pink);
}

// Lily pad colour: a per-leaf green, Worley cells (the seed's leaf texture) with lighter borders
// between them, faint radial veins and a reddish rim.
vec3 leafAlbedo(int i, const vec3& q) {
  const float radius = LEAVES[i].radius;
  const uint32_t seed = LEAF_SEED + uint32_t(i);
  const vec3 base = dm::mix(LEAF_GREEN_A, LEAF_GREEN_B, hash_to_unit(pcg_hash(seed)));
  const vec2 w = worley(vec2(q.x, q.z) * LEAF_CELL_FREQUENCY, seed);
  const float border = 1.0f - dm::smoothstep(0.0f, LEAF_BORDER_WIDTH, w.y - w.x);
  vec3 col = dm::mix(base * (0.85f + 0.3f * w.x), LEAF_VEIN, border * LEAF_BORDER_WEIGHT);
  const float rho = dm::sqrt(q.x * q.x + q.z * q.z);
  const float angle = dm::atan2(q.z, q.x);
  const float vein = 0.5f + 0.5f * dm::cos(angle * LEAF_VEIN_COUNT);
  col = col * (1.0f - LEAF_VEIN_DEPTH * vein * dm::smoothstep(0.1f, 0.6f, rho / radius));
  return dm::mix(col, LEAF_RIM, dm::smoothstep(0.9f, 1.0f, rho / radius) * LEAF_RIM_WEIGHT);
}

// A water drop on the surface (water_lily/droplets.h): its dome tilts the normal, most at the rim
// (the sharp highlight of the sun moves over it); under it, light bent away darkens a ring at the
// rim and gathers on the side away from the sun (the caustic); the water's highlight replaces the
// surface's own.
void addDroplet(Surface& s, const Droplet& d, const LilyUniforms& u) {
  if (!(d.cover > 0.0f)) return;
  const vec2 o = d.offset;
  const float r = dm::sqrt(o.x * o.x + o.y * o.y);
  s.tilt = vec3(o.x, 0.0f, o.y) * (DROP_SLOPE * d.cover);
  const float ring = dm::smoothstep(DROP_RING, 1.0f, r);
  const float caustic = dm::max(-(o.x * u.sun_dir.x + o.y * u.sun_dir.z), 0.0f) * (1.0f - r);
  const vec3 under = s.albedo * (1.0f - DROP_RING_DARK * ring + DROP_CAUSTIC * caustic);
  s.albedo = dm::mix(s.albedo, under, d.cover);
  s.shininess = DROP_SHININESS;
  s.specular = dm::mix(s.specular, DROP_SPECULAR, d.cover);
}

// Colour of the marched surface at p with normal n: which part, its albedo, whether light shines
// through, and the water drops on it (none for n = 0: the lilies the water mirrors).
Surface surfaceAt(const vec3& p, const vec3& n, bool leaves, const LilyUniforms& u) {
  const Nearest near = mapNearest(p, u, BOUND_MARGIN, leaves);
  if (near.flower >= 0) {
    const vec3 q = toFlower(p, near.flower);
    const float center = flowerCenter(q);
    const FlowerPlacement& fl = FLOWERS[near.flower];
    if (center < CENTER_COLOR_REACH)
      return Surface{dm::mix(CENTER_DEEP, CENTER_YELLOW,
                             dm::smoothstep(0.0f, CENTER_RADIUS, q.y - CENTER_Y + CENTER_RADIUS)),
                     0.0f, 0.0f, 0.0f, vec3(0.0f)};
    int layer = 0;
    float best = petalLayer(q, 0, fl.turn, u.curl[near.flower], u).x;
    for (int l = 1; l < PETAL_LAYERS; ++l) {
      const float d = petalLayer(q, l, fl.turn, u.curl[near.flower], u).x;
      if (d < best) {
        best = d;
        layer = l;
      }
    }
    const float along = dm::sqrt(q.x * q.x + q.z * q.z + q.y * q.y) / PETAL_TIP_REACH;
    Surface s{petalAlbedo(near.flower, along, layer), 1.0f, 0.0f, 0.0f, vec3(0.0f)};
    const vec2 plan(p.x - fl.xz.x, p.z - fl.xz.y);
    addDroplet(
        s, dropletAt(plan, DROP_SEED + uint32_t(near.flower), DROP_SHARE_PETAL * u.droplets, n.y),
        u);
    return s;
  }
  const int leaf = near.leaf >= 0 ? near.leaf : 0;
  Surface s{leafAlbedo(leaf, toLeaf(p, leaf, u)), 0.0f, LEAF_SHININESS, LEAF_SPECULAR, vec3(0.0f)};
  const vec2 c = leafCenter(leaf, u);
  const uint32_t seed = DROP_SEED + uint32_t(FLOWER_COUNT + leaf);
  addDroplet(s, dropletAt(vec2(p.x - c.x, p.z - c.y), seed, DROP_SHARE_PAD * u.droplets, n.y), u);
  return s;
}

// The seed's environment light: ambient from the sky and a diffuse term per light, each light
// with its soft shadow; petals also pass the sun through (translucency).
vec3 lightSurface(const Surface& s, const vec3& surface_n, const vec3& rd, float sun_shadow,
                  float fill_shadow, const LilyUniforms& u) {
  const vec3 n = safe_normalize(surface_n + s.tilt);
  const float ndl = dm::max(glm::dot(n, u.sun_dir), 0.0f);
  const float fill = dm::max(glm::dot(n, u.fill_dir), 0.0f);
  const float sky = 0.6f + 0.4f * n.y;
  vec3 light = u.sun_color * (ndl * sun_shadow) + FILL_COLOR * (fill * fill_shadow) +
               AMBIENT_SKY * (sky * (0.5f + 0.5f * fill_shadow));
  vec3 col = s.albedo * light;
  if (s.translucent > 0.0f) {
    // Light through the thin petal: the sun on the far side, strongest when looking towards it.
    const float back = dm::max(-glm::dot(n, u.sun_dir), 0.0f);
    const float towards = 0.5f + 0.5f * dm::max(glm::dot(rd, u.sun_dir), 0.0f);
    col = col + s.albedo * PETAL_TRANSMIT * u.sun_color *
                    (u.translucency * s.translucent * back * towards * sun_shadow);
  }
  if (s.shininess > 0.0f) {
    const float h = dm::max(glm::dot(reflectDir(rd, n), u.sun_dir), 0.0f);
    col = col + u.sun_color * (s.specular * dm::pow(h, s.shininess) * sun_shadow);
  }
  return col;
}

// The seed's reflection of a lily, "a lighter color that fits the scene": the lily's own colour
// lit as its sunlit side is (the sun from above and the sky), not as its underside. The mirror
// shows the flower broken by the ripples into patches of its colours; the underside, lit only by
// the dim ambient and the warm light through the petals, came out a dark reddish-brown.
vec3 reflectedLily(const Surface& s, const LilyUniforms& u) {
  return s.albedo * (u.sun_color * u.sun_dir.y + AMBIENT_SKY);
}

// Height of the water at (x, z): 3D FBM of the position and the water's time coordinate,
// cross-faded with its wrapped twin near the wrap (uniforms.cpp).
float waterHeight(float x, float z, const LilyUniforms& u) {
  const float h = fbm(vec3(x * WATER_FREQUENCY, z * WATER_FREQUENCY, u.water_time_a), WATER_OCTAVES,
                      WATER_SEED);
  if (!(u.water_blend > 0.0f)) return h;
  const float hb = fbm(vec3(x * WATER_FREQUENCY, z * WATER_FREQUENCY, u.water_time_b),
                       WATER_OCTAVES, WATER_SEED);
  return dm::mix(h, hb, u.water_blend);
}

// Submerged pads: flat notched discs SUBMERGED_DEPTH under the surface, seen along the refracted
// ray. Returns their coverage (0..1) at the point where the ray meets their plane, and colour.
float submergedLeaf(const vec3& w, const vec3& rd, vec3& col) {
  const vec3 down = safe_normalize(vec3(rd.x * REFRACT_BEND, rd.y, rd.z * REFRACT_BEND));
  const float t = SUBMERGED_DEPTH / -down.y;
  const vec3 s = w + down * t;
  float cover = 0.0f;
  for (int i = 0; i < SUBMERGED_COUNT; ++i) {
    const LeafPlacement& leaf = SUBMERGED[i];
    const float dx = s.x - leaf.xz.x, dz = s.z - leaf.xz.y;
    const float cs = dm::cos(leaf.notch_angle), sn = dm::sin(leaf.notch_angle);
    const vec3 q(cs * dx + sn * dz, 0.0f, cs * dz - sn * dx);
    const float disc = dm::sqrt(q.x * q.x + q.z * q.z) - leaf.radius;
    const float d = opSubtraction(leafNotch(q, leaf.radius), disc);
    const float c = 1.0f - dm::smoothstep(-SUBMERGED_EDGE, SUBMERGED_EDGE, d);
    if (c > cover) {
      cover = c;
      col =
          SUBMERGED_GREEN * (0.8f + 0.4f * hash_to_unit(pcg_hash(LEAF_SEED + 100u + uint32_t(i))));
    }
  }
  return cover;
}

vec3 applyFog(const vec3& col, float t, const LilyUniforms& u) {
  const float fog = dm::smoothstep(FOG_START_SHARE * u.fog_distance, u.fog_distance, t);
  return dm::mix(col, FOG_COLOR, fog);
}

// An eye under the water: the surface from below, a dim green-blue, darker looking down.
vec3 underwater(const vec3& rd) {
  return UNDERWATER * (0.4f + 0.6f * dm::max(rd.y, 0.0f));
}

}  // namespace

float mapScene(const vec3& p, bool leaves, const LilyUniforms& u, RayStats& stats) {
  stats.sdf_evals += 1;
  return mapNearest(p, u, BOUND_MARGIN, leaves).d;
}

vec3 throughPetal(const vec3& p, const vec3& n, float bias, const LilyUniforms& u,
                  RayStats& stats) {
  vec3 q = p - n * bias;
  for (int i = 0; i < PETAL_EXIT_STEPS; ++i) {
    const float d = mapScene(q, false, u, stats);
    if (d > bias) break;
    q = q - n * (bias - d);
  }
  return q;
}

vec3 skyColor(const vec3& d, const LilyUniforms& u) {
  const float y = dm::max(d.y, 0.0f);
  vec3 col = dm::mix(SKY_HORIZON, SKY_ZENITH, dm::sqrt(y));
  // The seed's FBM glow: soft bright clouds, strongest a little above the horizon.
  const float lift = 1.0f / (y + CLOUD_LIFT);
  const vec2 c(d.x * lift * CLOUD_SCALE + u.cloud_shift, d.z * lift * CLOUD_SCALE);
  const float cloud = fbm(c, CLOUD_OCTAVES, CLOUD_SEED);
  const float glow = dm::smoothstep(CLOUD_LOW, CLOUD_HIGH, cloud) * dm::smoothstep(0.0f, 0.25f, y);
  col = dm::mix(col, CLOUD_COLOR, glow * CLOUD_WEIGHT);
  const float s = dm::max(glm::dot(d, u.sun_dir), 0.0f);
  const float s2 = s * s;
  const float s4 = s2 * s2;
  return col + u.sun_color * (SUN_GLOW * s4 * s4 * (0.6f + 0.8f * cloud));
}

vec3 waterNormal(float x, float z, float dist, const LilyUniforms& u) {
  // The seed's bump falls off with the distance: calmer water far away.
  const float bump =
      u.water_bump * WATER_BUMP * (1.0f - dm::smoothstep(WATER_CALM_NEAR, WATER_CALM_FAR, dist));
  if (!(bump > 0.0f)) return vec3(0.0f, 1.0f, 0.0f);
  const float h = waterHeight(x, z, u);
  const float hx = waterHeight(x + WATER_DELTA, z, u);
  const float hz = waterHeight(x, z + WATER_DELTA, u);
  const float gx = (hx - h) / WATER_DELTA, gz = (hz - h) / WATER_DELTA;
  return safe_normalize(vec3(-gx * bump, 1.0f, -gz * bump));
}

vec2 shadowSpan(const vec3& ro, const vec3& ld, const LilyUniforms& u) {
  const vec2 span = slabSpan(ro, ld);
  const float tmax = u.naive ? u.max_dist : span.y;
  return vec2(dm::max(SHADOW_TMIN, u.naive ? 0.0f : span.x), tmax);
}

float softShadow(const vec3& ro, const vec3& ld, float k, int steps, const LilyUniforms& u,
                 RayStats& stats) {
  const vec2 span = shadowSpan(ro, ld, u);
  const float tmax = span.y;
  float t = span.x;
  float res = 1.0f;
  float ph = SHADOW_FIRST_PH;
  float step = 0.0f;
  for (int i = 0; i < steps && t < tmax; ++i) {
    stats.steps += 1;
    stats.sdf_evals += 1;
    // Only exact distances enter the penumbra estimate (see sdf_morph's softShadow).
    // Steps use the bound n.d; the penumbra and the hit test use the estimate n.est, which is
    // close to the true distance near a petal where the bound is up to its Lipschitz constant
    // too small (a darker, wider penumbra).
    const Nearest n = mapNearest(ro + ld * t, u, dm::max(BOUND_MARGIN, t / k));
    const float h = n.est;
    if (h < SHADOW_HIT_EPS) return 0.0f;
    if (n.exact) {
      // Quilez's improved estimate: the closest approach lies where the spheres of radius ph
      // (one step back) and h meet, y before this point. His h^2 / (2 ph) assumes the step was
      // ph; here steps are bounds shorter than the estimates, so the chord is placed for the
      // real step, and spheres that do not cut each other (one inside the other: the estimate
      // is not Lipschitz) or cut ahead of this point (y < 0) give no better estimate than h.
      float y = 0.0f;
      if (dm::abs(h - ph) < step)
        y = dm::max((h * h - ph * ph + step * step) / (2.0f * step), 0.0f);
      const float d = dm::sqrt(dm::max(h * h - y * y, 0.0f));
      res = dm::min(res, k * d / dm::max(t - y, SHADOW_MIN_DENOM));
      ph = h;
    } else {
      ph = SHADOW_FIRST_PH;
    }
    step = dm::max(n.d, SHADOW_MIN_STEP);
    t += step;
  }
  res = dm::clamp(res, 0.0f, 1.0f);
  return res * res * (3.0f - 2.0f * res);
}

vec3 grade(const vec3& c, const vec3& rd, const LilyUniforms& u) {
  vec3 col = dm::clamp(c, 0.0f, 1.0f);
  // Contrast: the seed's col^2 (3 - 2 col), mixed in by the contrast amount.
  col = dm::mix(col, col * col * (vec3(3.0f) - 2.0f * col), u.contrast);
  // Saturation: away from (or towards) the grey of dot(col, 0.4).
  const float grey = glm::dot(col, vec3(SATURATION_GREY));
  col = dm::mix(vec3(grey), col, u.saturation);
  // The seed's vignette from the ray's position on the screen (1 at the frame's sides): the
  // inverse of the square of (falloff r)^2 + 1, natural vignetting's cos^4 law in its rational
  // form.
  const float f = glm::dot(rd, u.cam_forward);
  const float sx = glm::dot(rd, u.cam_right) / f * u.inv_tan_half_fov * u.inv_aspect;
  const float sy = glm::dot(rd, u.cam_up) / f * u.inv_tan_half_fov;
  const float r2 = sx * sx + sy * sy;
  const float falloff = 1.0f + u.vignette * u.vignette * r2;
  return col * (1.0f / (falloff * falloff));
}

PrimarySpan primarySpan(const Ray& ray, const LilyUniforms& u) {
  PrimarySpan s;
  s.eps_per_t = u.hit_eps * ray.pixel_angle;
  s.t_water = intersectWater(ray.origin, ray.dir);
  s.water = s.t_water != NO_HIT && s.t_water < u.max_dist;
  const vec2 span = u.naive ? vec2(0.0f, u.max_dist) : slabSpan(ray.origin, ray.dir);
  s.t0 = span.x;
  s.t1 = dm::min(span.y, s.water ? s.t_water : u.max_dist);
  return s;
}

vec3 sceneRadiance(const Ray& ray, const LilyUniforms& u, RayStats& stats) {
  const PrimarySpan s = primarySpan(ray, u);
  float t = NO_HIT;
  if (s.t0 < s.t1)
    t = march(ray.origin, ray.dir, s.t0, s.t1, u.max_steps, s.eps_per_t, 0.0f, true, u, stats);
  return radianceAfterMarch(ray, s, t, u, stats);
}

vec3 radianceAfterMarch(const Ray& ray, const PrimarySpan& s, float t, const LilyUniforms& u,
                        RayStats& stats) {
  PixelShade ps = shadeBegin(ray, s, t, u, stats);
  traceSecondary(ps.rays, u, stats);
  return shadeEnd(ps, u);
}

PixelShade shadeBegin(const Ray& ray, const PrimarySpan& s, float t, const LilyUniforms& u,
                      RayStats& stats) {
  PixelShade ps;
  const vec3 ro = ray.origin, rd = ray.dir;
  ps.rd = rd;
  SecondaryRays& sr = ps.rays;
  if (u.hit_mask) {
    ps.col = t == NO_HIT ? vec3(HIT_ID_NONE)
                         : vec3(mapNearest(ro + rd * t, u, BOUND_MARGIN).flower >= 0 ? HIT_ID_FLOWER
                                                                                     : HIT_ID_LEAF);
    return ps;
  }
  if (u.surface != SURFACE_COLOUR) {  // the depth and normal passes: a lily, a pad or the water
    if (t != NO_HIT) {
      const vec3 p = ro + rd * t;
      ps.col = surfaceOutput(u.surface, t,
                             calcNormal(p, normalEps(ray.pixel_angle, t, u), true, u, stats));
    } else if (s.water) {
      const vec3 w = ro + rd * s.t_water;
      ps.col = surfaceOutput(u.surface, s.t_water, waterNormal(w.x, w.z, s.t_water, u));
    } else {
      ps.col = noSurface(u.surface);
    }
    return ps;
  }
  if (t != NO_HIT) {
    // A marched surface, fully lit: soft shadows from both lights. A surface turned away from a
    // light gets no direct light from it: no shadow ray either (translucent petals need the
    // sun's shadow from both sides).
    ps.kind = SHADE_SURFACE;
    ps.dist = t;
    ps.p = ro + rd * t;
    ps.n = calcNormal(ps.p, normalEps(ray.pixel_angle, t, u), true, u, stats);
    ps.surface = surfaceAt(ps.p, ps.n, true, u);
    const float bias = surfaceBias(hitEps(s.eps_per_t, t, u));
    const vec3 o = ps.p + ps.n * bias;
    sr.sun = glm::dot(ps.n, u.sun_dir) > 0.0f || ps.surface.translucent > 0.0f;
    sr.sun_origin = glm::dot(ps.n, u.sun_dir) > 0.0f ? o : throughPetal(ps.p, ps.n, bias, u, stats);
    sr.fill = true;
    sr.fill_origin = o;
  } else if (s.water) {
    // The water: what it mirrors (the lilies, lit and unshadowed, fading with the distance they
    // are seen at, over the sky; as in the seed only the lilies are tested: the pads lie flat on
    // the water, and a reflected ray creeping over a pad's rim would cost its whole step budget,
    // hard case horizon_grazing), and the shadows on it.
    ps.kind = SHADE_WATER;
    ps.dist = s.t_water;
    ps.p = ro + rd * s.t_water;
    ps.n = waterNormal(ps.p.x, ps.p.z, s.t_water, u);
    vec3 r = reflectDir(rd, ps.n);
    r.y = dm::abs(r.y);  // a bump cannot turn the reflection into the water
    const float bias = surfaceBias(hitEps(s.eps_per_t, s.t_water, u));
    const vec3 wo = vec3(ps.p.x, bias, ps.p.z);
    const vec2 span = slabSpan(wo, r);
    sr.reflect_origin = wo;
    sr.reflect_dir = r;
    sr.reflect_t0 = span.x;
    sr.reflect_t1 = dm::min(span.y, u.naive ? u.max_dist : REFLECT_MAX_DIST);
    sr.reflect = span.x < sr.reflect_t1;
    sr.reflect_eps_per_t = s.eps_per_t * REFLECT_HIT_SCALE;
    sr.reflect_t_before = s.t_water;
    sr.sun = sr.fill = true;
    sr.sun_origin = sr.fill_origin = wo;
  } else {
    ps.col = grade(ro.y < 0.0f ? underwater(rd) : skyColor(rd, u), rd, u);
  }
  return ps;
}

void traceSecondary(SecondaryRays& sr, const LilyUniforms& u, RayStats& stats) {
  if (sr.reflect) {
    const RelaxedMarchSettings s{u.reflect_steps, u.naive,     u.step_factor,
                                 u.hit_eps,       MIN_HIT_EPS, NO_HIT};
    sr.reflect_t = relaxed_march([&](const vec3& p) { return mapScene(p, false, u, stats); },
                                 sr.reflect_origin, sr.reflect_dir, sr.reflect_t0, sr.reflect_t1,
                                 sr.reflect_eps_per_t, sr.reflect_t_before, s, stats);
  }
  if (sr.sun)
    sr.sun_shadow = softShadow(sr.sun_origin, u.sun_dir, u.shadow_k, u.shadow_steps, u, stats);
  if (sr.fill)
    sr.fill_shadow = softShadow(sr.fill_origin, u.fill_dir, u.shadow_k * FILL_SHADOW_SOFTNESS,
                                u.shadow_steps / 2, u, stats);
}

vec3 shadeEnd(const PixelShade& ps, const LilyUniforms& u) {
  if (ps.kind == SHADE_DONE) return ps.col;
  const SecondaryRays& sr = ps.rays;
  const vec3 rd = ps.rd;
  vec3 col;
  if (ps.kind == SHADE_SURFACE) {
    col = lightSurface(ps.surface, ps.n, rd, sr.sun_shadow, sr.fill_shadow, u);
  } else {
    const vec3 w = ps.p, r = sr.reflect_dir;
    const float fresnel = schlick(-glm::dot(ps.n, rd), WATER_F0);
    vec3 mirror = skyColor(r, u);
    if (sr.reflect && sr.reflect_t != NO_HIT) {
      const float t = sr.reflect_t;
      const vec3 q = sr.reflect_origin + r * t;
      const vec3 lit = reflectedLily(surfaceAt(q, vec3(0.0f), false, u), u);
      mirror = dm::mix(mirror, lit, dm::exp(-REFLECT_FALLOFF * t));
    }
    const float sun = sr.sun_shadow, fill = sr.fill_shadow;
    // The water body: a deep colour lit by sun and sky, over the submerged pads.
    vec3 body = WATER_DEEP * (WATER_SUN_SHARE * sun + (1.0f - WATER_SUN_SHARE) * fill);
    vec3 leaf_col(0.0f);
    const float cover = submergedLeaf(w, rd, leaf_col);
    const vec3 leaf_lit = leaf_col * (u.sun_color * (u.sun_dir.y * sun) + AMBIENT_SKY * fill);
    body = dm::mix(body, leaf_lit * SUBMERGED_TRANSMIT, cover);
    const float glint = dm::pow(dm::max(glm::dot(r, u.sun_dir), 0.0f), SUN_GLINT_POWER);
    const vec3 mirror_lit = mirror + u.sun_color * (SUN_GLINT * glint * sun);
    col = dm::mix(body, mirror_lit, fresnel);
  }
  return grade(applyFog(col, ps.dist, u), rd, u);
}

}  // namespace sdfreel::water_lily
