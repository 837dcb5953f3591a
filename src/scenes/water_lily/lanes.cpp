#include "scenes/water_lily/lanes.h"

#include "scenes/common/relaxed_march.h"
#include "scenes/water_lily/geometry.h"
#include "scenes/water_lily/render.h"
#include "scenes/water_lily/secondary_lanes.h"

namespace sdfreel::water_lily {
namespace {}  // namespace

// mapNearest(p, u, margin, leaves).d in lanes: a part whose bound exceeds the margin in every
// lane contributes its bound without its exact distance being evaluated.
F8 mapDistanceLanes(const V3x8& p, const LilyUniforms& u, float margin, bool leaves) {
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

namespace {

// march() of render.cpp for the lanes in `active` (primary rays: all pads and flowers, no path
// before).
F8 march_lanes(const V3x8& ro, const V3x8& rd, F8 tmin, F8 tmax, M8 active, F8 eps_per_t,
               const LilyUniforms& u, RayStats& stats) {
  const RelaxedMarchSettings s{u.max_steps, u.naive, u.step_factor, u.hit_eps, MIN_HIT_EPS, NO_HIT};
  return sdfreel::march_lanes(
      [&u](const V3x8& p) { return mapDistanceLanes(p, u, BOUND_MARGIN, true); }, ro, rd, tmin,
      tmax, active, eps_per_t, splat(0.0f), s, stats);
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
  if (any(active))
    t = march_lanes(V3x8(rays.origin), rays.dir, t0, t1, active, eps_per_t, u, stats);
  PixelShade shade[LANES];
  SecondaryRays secondary[LANES];
  for (int i = 0; i < rays.count; ++i) {
    const LaneEvalScope lane(stats, i);
    shade[i] = shadeBegin(rays.ray(i), spans[i], t[i], u, stats);
    secondary[i] = shade[i].rays;
  }
  traceSecondaryLanes(secondary, rays.count, u, stats);
  for (int i = 0; i < rays.count; ++i) {
    shade[i].rays = secondary[i];
    out[i] = shadeEnd(shade[i], u);
  }
}

std::vector<DistanceFunction> lilyDistanceFunctions(const LilyUniforms& u) {
  DistanceFunction scene{"mapScene", nullptr, nullptr};
  scene.scalar = [u](const float* x, const float* y, const float* z, float* d, int n) {
    for (int i = 0; i < n; ++i) d[i] = mapNearest(glm::vec3(x[i], y[i], z[i]), u, BOUND_MARGIN).d;
  };
  scene.lanes = [u](const float* x, const float* y, const float* z, float* d, int n) {
    for (int i = 0; i < n; i += LANES)
      store8(d + i, mapDistanceLanes(V3x8(load8(x + i), load8(y + i), load8(z + i)), u,
                                     BOUND_MARGIN, true));
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
