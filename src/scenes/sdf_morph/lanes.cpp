#include "scenes/sdf_morph/lanes.h"

#include "scenes/common/relaxed_march.h"
#include "scenes/common/surface_output.h"
#include "scenes/sdf_morph/environment.h"
#include "scenes/sdf_morph/geometry.h"
#include "scenes/sdf_morph/march.h"
#include "scenes/sdf_morph/render.h"
#include "sdf/sdf.h"

namespace sdfreel::sdf_morph {
namespace {

using glm::vec3;

F8 mapScene_lanes(const V3x8& p, const MorphUniforms& u) {
  M8 exact;
  return mapSceneBounded(p, u, OBJECT_BOUND_MARGIN, exact);
}

// march() of sdf_morph/render.cpp for the lanes in `active`, `max_steps` at most.
F8 march_lanes(const V3x8& ro, const V3x8& rd, F8 tmin, F8 tmax, M8 active, int max_steps,
               F8 eps_per_t, F8 t_before, const MorphUniforms& u, RayStats& stats) {
  const RelaxedMarchSettings s{max_steps, u.naive, u.step_factor, u.hit_eps, MIN_HIT_EPS, NO_HIT};
  return sdfreel::march_lanes([&u](const V3x8& p) { return mapScene_lanes(p, u); }, ro, rd, tmin,
                              tmax, active, eps_per_t, t_before, s, stats);
}

// hitEps, normalEps and surfaceBias of sdf_morph/march.h in lanes.
F8 hitEps_lanes(F8 eps_per_t, F8 t, const MorphUniforms& u) {
  return u.naive ? splat(u.hit_eps) : dm::max(MIN_HIT_EPS, eps_per_t * t);
}
F8 normalEps_lanes(float pixel_angle, F8 t, const MorphUniforms& u) {
  return u.naive ? splat(u.normal_eps) : dm::max(MIN_NORMAL_EPS, u.normal_eps * pixel_angle * t);
}
F8 surfaceBias_lanes(F8 eps) {
  return dm::max(MIN_SURFACE_BIAS, SURFACE_BIAS_FACTOR * eps);
}

// primarySpan of sdf_morph/render.cpp for the eight rays (their origin is shared).
struct PrimarySpansLanes {
  F8 eps_per_t, t_floor;
  M8 floor_visible;
  F8 t0, t1;
};
PrimarySpansLanes primarySpans_lanes(const RayPacket& rays, const MorphUniforms& u) {
  const V3x8& rd = rays.dir;
  PrimarySpansLanes s;
  s.eps_per_t = splat(u.hit_eps * rays.pixel_angle);
  // intersectFloor
  const F8 t = -rays.origin.y / rd.y;
  s.t_floor = select(rd.y == 0.0f, splat(NO_HIT), select(t > 0.0f, t, splat(NO_HIT)));
  s.floor_visible = (s.t_floor > 0.0f) & (s.t_floor < u.max_dist);
  const F8 tmax = select(s.floor_visible, s.t_floor, splat(u.max_dist));
  // groupSpan: intersectSphere with the group's sphere, or everything for the naive preset
  F8 enter = splat(0.0f), exit = splat(u.max_dist);
  if (!u.naive) {
    const vec3 oc = rays.origin - groupBoundCenter();
    const F8 b = vdot(oc, rd);
    const V3x8 q = oc - b * rd;
    const F8 disc = GROUP_BOUND_RADIUS * GROUP_BOUND_RADIUS - vdot(q, q);
    const F8 root = dm::sqrt(disc);
    const M8 miss = disc < 0.0f;
    enter = select(miss, splat(MISS_SPAN), -b - root);
    exit = select(miss, splat(-MISS_SPAN), -b + root);
  }
  s.t0 = dm::max(enter, 0.0f);
  s.t1 = dm::min(exit, tmax);
  return s;
}

V3x8 safe_normalize_lanes(const V3x8& v) {
  const F8 len2 = vdot(v, v);
  const V3x8 up(splat(0.0f), splat(1.0f), splat(0.0f));
  return select(len2 > SAFE_NORMALIZE_MIN_LENGTH2, v / dm::sqrt(len2), up);
}

// calcNormal in lanes; lanes outside `active` are computed but not counted.
V3x8 calcNormal_lanes(const V3x8& p, F8 e, M8 active, const MorphUniforms& u, RayStats& stats) {
  stats.count_evals(active, 4);
  const vec3 a(1.0f, -1.0f, -1.0f), b(-1.0f, -1.0f, 1.0f), c(-1.0f, 1.0f, -1.0f),
      d(1.0f, 1.0f, 1.0f);
  return safe_normalize_lanes(a * mapScene_lanes(p + a * e, u) + b * mapScene_lanes(p + b * e, u) +
                              c * mapScene_lanes(p + c * e, u) + d * mapScene_lanes(p + d * e, u));
}

// softShadow towards the key light from ro, for the lanes in `active` (others return 1).
F8 softShadow_lanes(const V3x8& ro, M8 active, const MorphUniforms& u, RayStats& stats) {
  const vec3 rd = u.boxes[0].dir;
  F8 span_in, span_out;
  for (int i = 0; i < LANES; ++i) {
    const glm::vec2 span = groupSpan(ro.lane(i), rd, u);
    span_in[i] = span.x;
    span_out[i] = span.y;
  }
  M8 live = active & ~(span_out <= 0.0f);  // the scalar `span.y <= 0: lit`
  M8 blocked = splat_mask(false);
  const M8 marched = live;
  F8 t = dm::max(SHADOW_TMIN, span_in);
  F8 res = splat(1.0f);
  F8 ph = splat(SHADOW_FIRST_PH);
  for (int i = 0; i < u.shadow_steps; ++i) {
    live &= t < span_out;
    if (!any(live)) break;
    const uint64_t n = count_lanes(live);
    stats.steps += n;
    stats.count_evals(live);
    const F8 margin = dm::max(OBJECT_BOUND_MARGIN, t / u.shadow_k);
    M8 exact;
    const F8 h = mapSceneBounded(ro + rd * t, u, margin, exact);
    const M8 hit = live & (h < SHADOW_HIT_EPS);
    blocked |= hit;
    live &= ~hit;
    const M8 estimate = live & exact;
    const F8 y = h * h / (2.0f * ph);
    const F8 d = dm::sqrt(dm::max(h * h - y * y, 0.0f));
    res = select(estimate, dm::min(res, u.shadow_k * d / dm::max(t - y, SHADOW_MIN_DENOM)), res);
    ph = select(estimate, h, select(live, splat(SHADOW_FIRST_PH), ph));
    t = select(live, t + h, t);
  }
  res = dm::clamp(res, 0.0f, 1.0f);
  const F8 shade = res * res * (3.0f - 2.0f * res);
  return select(blocked, splat(0.0f), select(marched, shade, splat(1.0f)));
}

// ambientOcclusion in lanes; lanes outside `active` are computed but not counted.
F8 ambientOcclusion_lanes(const V3x8& p, const V3x8& n, M8 active, const MorphUniforms& u,
                          RayStats& stats) {
  stats.count_evals(active, AO_TAPS);
  F8 occ = splat(0.0f);
  float scale = 1.0f;
  for (int i = 0; i < AO_TAPS; ++i) {
    const float h = aoTapHeight(i);
    const F8 d = mapScene_lanes(p + n * h, u);
    occ += (h - d) * scale;
    scale *= AO_FALLOFF;
  }
  F8 ao;
  for (int i = 0; i < LANES; ++i) ao[i] = aoFromSum(occ[i]);
  return ao;
}

}  // namespace

void radiance_lanes(const RayPacket& rays, const MorphUniforms& u, glm::vec3* out,
                    RayStats& stats) {
  const M8 valid = rays.valid();
  const V3x8 ro(rays.origin);
  const V3x8& rd = rays.dir;
  // Primary rays: spans lane by lane, then one march.
  const PrimarySpansLanes spans = primarySpans_lanes(rays, u);
  const F8 t0 = spans.t0, t1 = spans.t1, eps_per_t = spans.eps_per_t;
  const M8 marched = valid & (t0 < t1);
  const F8 t = march_lanes(ro, rd, t0, t1, marched, u.max_steps, eps_per_t, splat(0.0f), u, stats);
  const M8 hit = marched & (t != NO_HIT);
  const V3x8 p = ro + rd * t;
  if (u.hit_mask) {
    const M8 object = isObject(p, u);
    for (int i = 0; i < rays.count; ++i)
      out[i] = vec3(!lane(hit, i)     ? HIT_ID_NONE
                    : lane(object, i) ? HIT_ID_OBJECT
                                      : HIT_ID_PEDESTAL);
    return;
  }
  // Normals and kinds of the marched hits.
  const F8 e = normalEps_lanes(rays.pixel_angle, t, u);
  F8 bias = surfaceBias_lanes(hitEps_lanes(eps_per_t, t, u));
  V3x8 n = calcNormal_lanes(p, e, hit, u, stats);
  if (u.surface != SURFACE_COLOUR) {  // the depth and normal passes: the marched hit or the floor
    for (int i = 0; i < rays.count; ++i)
      out[i] = lane(hit, i) ? surfaceOutput(u.surface, t[i], n.lane(i))
               : lane(spans.floor_visible, i)
                   ? surfaceOutput(u.surface, spans.t_floor[i], vec3(0.0f, 1.0f, 0.0f))
                   : noSurface(u.surface);
    return;
  }
  const M8 object = hit & isObject(p, u);

  // The object's mirror: reflection rays marched together.
  M8 reflection_hit = splat_mask(false), reflection_object = splat_mask(false);
  V3x8 reflection_normal = n;
  ReflectionSpan rspans[LANES];
  V3x8 rro, rdir;
  F8 rt0, rt1;
  for (int i = 0; i < LANES; ++i) {
    if (!lane(object, i)) {  // no reflection: an empty span
      rro.set_lane(i, rays.origin);
      rdir.set_lane(i, rd.lane(i));
      rt0[i] = rt1[i] = 0.0f;
      continue;
    }
    const vec3 r = reflectDir(rd.lane(i), n.lane(i));
    rspans[i] = reflectionSpan(p.lane(i), n.lane(i), r, t[i], eps_per_t[i], u);
    rro.set_lane(i, rspans[i].ro);
    rdir.set_lane(i, r);
    rt0[i] = rspans[i].t0;
    rt1[i] = rspans[i].t1;
  }
  if (any(object)) {
    const M8 rmarched = object & (rt0 < rt1);
    const F8 rt =
        march_lanes(rro, rdir, rt0, rt1, rmarched, u.reflect_steps, eps_per_t, t, u, stats);
    const M8 rhit = rmarched & (rt != NO_HIT);
    M8 robject = splat_mask(false);
    V3x8 nq = n;
    if (any(rhit)) {
      const V3x8 q = rro + rdir * rt;
      nq = calcNormal_lanes(q, normalEps_lanes(rays.pixel_angle, t + rt, u), rhit, u, stats);
      robject = isObject(q, u);
    }
    reflection_hit = rhit;
    reflection_object = robject;
    reflection_normal = nq;
  }

  // Surfaces that need shadow and occlusion: marched hits and the floor, each with p, n, bias.
  const M8 floor = valid & ~hit & spans.floor_visible;
  const V3x8 sp = select(floor, ro + rd * spans.t_floor, p);
  n = select(floor, V3x8(vec3(0.0f, 1.0f, 0.0f)), n);
  bias = select(floor, surfaceBias_lanes(hitEps_lanes(eps_per_t, spans.t_floor, u)), bias);
  const M8 surface = hit | floor;
  const M8 shadowed = surface & needsShadow(n, u);
  const M8 occluded = surface & needsOcclusion(sp, u);
  F8 shadow = splat(1.0f), ao = splat(1.0f);
  if (any(shadowed))
    shadow = select(shadowed, softShadow_lanes(sp + n * bias, shadowed, u, stats), shadow);
  if (any(occluded)) ao = select(occluded, ambientOcclusion_lanes(sp, n, occluded, u, stats), ao);

  // The studio, once per lane in the one direction its surface needs: the ray itself (misses,
  // floor), the mirror direction (pedestal, object reflections that hit) or the reflection ray.
  V3x8 env_dir = rd;
  for (int i = 0; i < LANES; ++i) {
    if (lane(object, i))
      env_dir.set_lane(i, lane(reflection_hit, i)
                              ? reflectDir(rdir.lane(i), reflection_normal.lane(i))
                              : rdir.lane(i));
    else if (lane(hit, i))
      env_dir.set_lane(i, reflectDir(rd.lane(i), n.lane(i)));
  }
  const V3x8 env = studio(env_dir, u);

  for (int i = 0; i < rays.count; ++i) {
    const vec3 d = rd.lane(i);
    if (lane(object, i)) {
      const vec3 r = rdir.lane(i);
      const vec3 reflection = lane(reflection_hit, i)
                                  ? shadeReflectionHit(reflection_normal.lane(i), r,
                                                       lane(reflection_object, i), env.lane(i), u)
                                  : shadeReflectionMiss(rspans[i], r, env.lane(i), u);
      out[i] = shadeObjectLit(n.lane(i), d, reflection, shadow[i], ao[i], u);
    } else if (lane(hit, i)) {
      out[i] = shadePedestalLit(n.lane(i), d, shadow[i], ao[i], env.lane(i), u);
    } else if (lane(floor, i)) {
      out[i] = shadeFloorLit(sp.lane(i), shadow[i], ao[i], env.lane(i), u);
    } else {
      out[i] = env.lane(i);
    }
  }
}

std::vector<DistanceFunction> morphDistanceFunctions(const MorphUniforms& u) {
  DistanceFunction scene{"mapScene", nullptr, nullptr};
  scene.scalar = [u](const float* x, const float* y, const float* z, float* d, int n) {
    for (int i = 0; i < n; ++i) {
      bool exact;
      d[i] = mapSceneBounded(vec3(x[i], y[i], z[i]), u, OBJECT_BOUND_MARGIN, exact);
    }
  };
  scene.lanes = [u](const float* x, const float* y, const float* z, float* d, int n) {
    for (int i = 0; i < n; i += LANES)
      store8(d + i, mapScene_lanes(V3x8(load8(x + i), load8(y + i), load8(z + i)), u));
  };
  DistanceFunction object{"mapObject", nullptr, nullptr};
  object.scalar = [u](const float* x, const float* y, const float* z, float* d, int n) {
    for (int i = 0; i < n; ++i) d[i] = mapObject(vec3(x[i], y[i], z[i]), u);
  };
  object.lanes = [u](const float* x, const float* y, const float* z, float* d, int n) {
    for (int i = 0; i < n; i += LANES)
      store8(d + i, mapObject(V3x8(load8(x + i), load8(y + i), load8(z + i)), u));
  };
  return {scene, object};
}

}  // namespace sdfreel::sdf_morph
