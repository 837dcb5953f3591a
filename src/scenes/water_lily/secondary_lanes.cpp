#include "scenes/water_lily/secondary_lanes.h"

#include "scenes/common/relaxed_march.h"
#include "scenes/water_lily/geometry.h"
#include "scenes/water_lily/shadow.h"

namespace sdfreel::water_lily {
namespace {

// mapNearest (geometry.h) with every leaf, in lanes: what the soft shadow reads of it.
struct Nearest8 {
  F8 d, est;
  M8 exact;
};

Nearest8 mapNearest8(const V3x8& p, const LilyUniforms& u, F8 margin) {
  Nearest8 n{splat(BIG_DISTANCE), splat(BIG_DISTANCE), splat_mask(true)};
  for (int i = 0; i < LEAF_COUNT; ++i) {
    const F8 b = u.naive ? splat(-1.0f) : leafBound(p, i, u);
    const M8 far = b > margin;
    const F8 d = all(far) ? b : select(far, b, lilyPad(p, i, u));
    const M8 nearer = d < n.d;
    n.d = select(nearer, d, n.d);
    n.est = select(nearer, d, n.est);
    n.exact = select(nearer, ~far, n.exact);
  }
  for (int f = 0; f < FLOWER_COUNT; ++f) {
    const F8 b = u.naive ? splat(-1.0f) : flowerBound(p, f);
    const M8 far = b > margin;
    F8 x = b, y = b;
    if (!all(far)) {
      const Dist2<F8> pair = lilyFlowerPair(p, f, u);
      x = select(far, b, pair.x);
      y = select(far, b, pair.y);
    }
    const M8 nearer = x < n.d;
    n.d = select(nearer, x, n.d);
    n.est = select(nearer, y, n.est);
    n.exact = select(nearer, ~far, n.exact);
  }
  return n;
}

}  // namespace

F8 softShadowLanes(const V3x8& ro, const glm::vec3& ld, float k, int steps, M8 active,
                   const LilyUniforms& u, RayStats& stats) {
  F8 t = splat(0.0f), tmax = splat(0.0f);
  for (int i = 0; i < LANES; ++i) {
    if (!active[i]) continue;
    const glm::vec2 span = shadowSpan(ro.lane(i), ld, u);
    t[i] = span.x;
    tmax[i] = span.y;
  }
  F8 res = splat(1.0f), ph = splat(SHADOW_FIRST_PH), step = splat(0.0f);
  M8 blocked = splat_mask(false);
  for (int i = 0; i < steps; ++i) {
    active &= t < tmax;
    if (!any(active)) break;
    const uint64_t n = count_lanes(active);
    stats.steps += n;
    stats.count_evals(active);
    const Nearest8 nn = mapNearest8(ro + ld * t, u, dm::max(splat(BOUND_MARGIN), t / k));
    const F8 h = nn.est;
    const M8 hit = active & (h < SHADOW_HIT_EPS);
    blocked |= hit;
    active &= ~hit;
    // softShadow's improved estimate (render.cpp), in every lane, kept where exact.
    const M8 exact = active & nn.exact;
    const M8 cut = dm::abs(h - ph) < step;
    const F8 y =
        select(cut, dm::max((h * h - ph * ph + step * step) / (2.0f * step), 0.0f), splat(0.0f));
    const F8 d = dm::sqrt(dm::max(h * h - y * y, 0.0f));
    res = select(exact, dm::min(res, k * d / dm::max(t - y, SHADOW_MIN_DENOM)), res);
    ph = select(exact, h, select(active, splat(SHADOW_FIRST_PH), ph));
    step = select(active, dm::max(nn.d, SHADOW_MIN_STEP), step);
    t = select(active, t + step, t);
  }
  res = dm::clamp(res, 0.0f, 1.0f);
  return select(blocked, splat(0.0f), res * res * (3.0f - 2.0f * res));
}

void traceSecondaryLanes(SecondaryRays* rays, int count, const LilyUniforms& u, RayStats& stats) {
  const V3x8 zero(glm::vec3(0.0f));
  // The reflections: flowers only, with the reflection's step budget and hit threshold.
  M8 reflect = splat_mask(false);
  V3x8 ro = zero, rd = zero;
  F8 t0 = splat(0.0f), t1 = splat(0.0f), eps_per_t = splat(0.0f), t_before = splat(0.0f);
  for (int i = 0; i < count; ++i) {
    const SecondaryRays& r = rays[i];
    if (!r.reflect) continue;
    reflect[i] = -1;
    ro.set_lane(i, r.reflect_origin);
    rd.set_lane(i, r.reflect_dir);
    t0[i] = r.reflect_t0;
    t1[i] = r.reflect_t1;
    eps_per_t[i] = r.reflect_eps_per_t;
    t_before[i] = r.reflect_t_before;
  }
  if (any(reflect)) {
    const RelaxedMarchSettings s{u.reflect_steps, u.naive,     u.step_factor,
                                 u.hit_eps,       MIN_HIT_EPS, NO_HIT};
    const F8 t =
        march_lanes([&u](const V3x8& p) { return mapDistanceLanes(p, u, BOUND_MARGIN, false); }, ro,
                    rd, t0, t1, reflect, eps_per_t, t_before, s, stats);
    for (int i = 0; i < count; ++i)
      if (rays[i].reflect) rays[i].reflect_t = t[i];
  }
  // The soft shadows towards the sun and the fill light.
  M8 sun = splat_mask(false), fill = splat_mask(false);
  V3x8 sun_o = zero, fill_o = zero;
  for (int i = 0; i < count; ++i) {
    if (rays[i].sun) sun[i] = -1, sun_o.set_lane(i, rays[i].sun_origin);
    if (rays[i].fill) fill[i] = -1, fill_o.set_lane(i, rays[i].fill_origin);
  }
  if (any(sun)) {
    const F8 v = softShadowLanes(sun_o, u.sun_dir, u.shadow_k, u.shadow_steps, sun, u, stats);
    for (int i = 0; i < count; ++i)
      if (rays[i].sun) rays[i].sun_shadow = v[i];
  }
  if (any(fill)) {
    const F8 v = softShadowLanes(fill_o, u.fill_dir, u.shadow_k * FILL_SHADOW_SOFTNESS,
                                 u.shadow_steps / 2, fill, u, stats);
    for (int i = 0; i < count; ++i)
      if (rays[i].fill) rays[i].fill_shadow = v[i];
  }
}

}  // namespace sdfreel::water_lily
