#include "scenes/water_lily/lanes.h"

#include "scenes/water_lily/geometry.h"
#include "scenes/water_lily/render.h"

namespace sdfreel::water_lily {
namespace {

// mapNearest(p, u, margin, leaves).d in lanes: a part whose bound exceeds the margin in every
// lane contributes its bound without its exact distance being evaluated.
F8 mapDistance8(const V3x8& p, const LilyUniforms& u, float margin, bool leaves) {
  F8 d = splat(BIG_DISTANCE);
  for (int i = 0; i < (leaves ? LEAF_COUNT : 0); ++i) {
    const F8 b = u.naive ? splat(-1.0f) : leafBound(p, i, u);
    const M8 far = b > margin;
    const F8 di = all(far) ? b : select(far, b, lilyPad(p, i, u));
    d = select(di < d, di, d);
  }
  for (int f = 0; f < FLOWER_COUNT; ++f) {
    const F8 b = u.naive ? splat(-1.0f) : flowerBound(p, f);
    const M8 far = b > margin;
    const F8 df = all(far) ? b : select(far, b, lilyFlowerPair(p, f, u).x);
    d = select(df < d, df, d);
  }
  return d;
}

// march() of render.cpp for the lanes in `active` (primary rays: all pads and flowers, no path
// before): per-lane t, omega, prev_d and step as masks. Inactive lanes return NO_HIT.
F8 march8(const V3x8& ro, const V3x8& rd, F8 tmin, F8 tmax, M8 active, F8 eps_per_t,
          const LilyUniforms& u, RayStats& stats) {
  F8 t = tmin;
  F8 omega = splat(u.naive ? 1.0f : u.step_factor);
  F8 prev_d = splat(0.0f);
  F8 step = splat(0.0f);
  F8 result = splat(NO_HIT);
  for (int i = 0; i < u.max_steps && any(active); ++i) {
    const uint64_t n = count_lanes(active);
    stats.steps += n;
    stats.sdf_evals += n;
    const F8 d = mapDistance8(ro + rd * t, u, BOUND_MARGIN, true);
    const M8 back = active & (omega > 1.0f) & (dm::abs(d) + prev_d < step);
    t = select(back, t + (prev_d - step), t);
    step = select(back, prev_d, step);
    omega = select(back, splat(1.0f), omega);
    M8 go = active & ~back;
    const F8 eps = u.naive ? splat(u.hit_eps) : dm::max(MIN_HIT_EPS, eps_per_t * (0.0f + t));
    const M8 hit = go & (d < eps);
    result = select(hit, t, result);
    active &= ~hit;
    go &= ~hit;
    const F8 new_step = d * omega;
    step = select(go, new_step, step);
    prev_d = select(go, d, prev_d);
    t = select(go, t + new_step, t);
    const M8 over = go & (t > tmax);
    const M8 miss = over & ((omega <= 1.0f) | (t - step + d > tmax));
    active &= ~miss;
    const M8 fall_back = over & ~miss;
    t = select(fall_back, t + (d - step), t);
    step = select(fall_back, d, step);
    omega = select(fall_back, splat(1.0f), omega);
  }
  stats.capped += count_lanes(active);
  return select(active, t, result);
}

}  // namespace

void radiancePacket(const RayPacket& rays, const LilyUniforms& u, glm::vec3* out, RayStats& stats) {
  PrimarySpan spans[LANES];
  F8 t0, t1, eps_per_t;
  M8 active = splat_mask(false);
  for (int i = 0; i < LANES; ++i) {
    spans[i] = primarySpan(rays.ray(i), u);
    t0[i] = spans[i].t0;
    t1[i] = spans[i].t1;
    eps_per_t[i] = spans[i].eps_per_t;
    active[i] = i < rays.count && spans[i].t0 < spans[i].t1 ? -1 : 0;
  }
  F8 t = splat(NO_HIT);
  if (any(active)) t = march8(V3x8(rays.origin), rays.dir, t0, t1, active, eps_per_t, u, stats);
  for (int i = 0; i < rays.count; ++i)
    out[i] = radianceAfterMarch(rays.ray(i), spans[i], t[i], u, stats);
}

std::vector<DistanceFunction> lilyDistanceFunctions(const LilyUniforms& u) {
  DistanceFunction scene{"mapScene", nullptr, nullptr};
  scene.scalar = [u](const float* x, const float* y, const float* z, float* d, int n) {
    for (int i = 0; i < n; ++i) d[i] = mapNearest(glm::vec3(x[i], y[i], z[i]), u, BOUND_MARGIN).d;
  };
  scene.lanes = [u](const float* x, const float* y, const float* z, float* d, int n) {
    for (int i = 0; i < n; i += LANES)
      store8(d + i,
             mapDistance8(V3x8(load8(x + i), load8(y + i), load8(z + i)), u, BOUND_MARGIN, true));
  };
  DistanceFunction flower{"lilyFlower", nullptr, nullptr};
  flower.scalar = [u](const float* x, const float* y, const float* z, float* d, int n) {
    for (int i = 0; i < n; ++i) d[i] = lilyFlower(glm::vec3(x[i], y[i], z[i]), 0, u);
  };
  flower.lanes = [u](const float* x, const float* y, const float* z, float* d, int n) {
    for (int i = 0; i < n; i += LANES)
      store8(d + i, lilyFlower(V3x8(load8(x + i), load8(y + i), load8(z + i)), 0, u));
  };
  return {scene, flower};
}

}  // namespace sdfreel::water_lily
