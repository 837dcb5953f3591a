// lantern_festival's eight-lane path, for every preset: the primary marches (lake, lanterns),
// the water normal, the reflection and its march, and the sky run in lanes; the shading of lantern
// and water hits runs per lane with the scalar functions. Every lane gets radiance()'s bits and
// stats (tests/scenes/packet_path_test.cpp).
#include "scenes/common/surface_output.h"
#include "scenes/lantern_festival/march_lanes.h"
#include "scenes/lantern_festival/scene.h"

namespace sdfreel::lantern_festival {

namespace {

// LanternFestivalScene::normalEps in lanes.
F8 normalEps_lanes(const MarchSettings& m, F8 t, float pixel_angle) {
  if (m.naive) return splat(m.normal_eps);
  return dm::max(m.normal_eps * t * pixel_angle, 1e-4f);
}

// LanternFestivalScene::marchLanterns in lanes: the preset's march, and the lantern hit.
CellHitLanes marchLanterns_lanes(const LanternField& f, const MarchSettings& m, bool reference,
                                 const V3x8& o, const V3x8& dir, F8 t_max, const MarchLimits& lim,
                                 F8 t_offset, M8 active, RayStats& stats) {
  if (m.naive) {
    const NaiveHitLanes h = marchNaive_lanes(f, o, dir, t_max, false, lim, t_offset, active, stats);
    CellHitLanes out{h.hit, h.t, {}};
    for (int i = 0; i < LANES; ++i) out.cell[i] = h.cell[i];
    return out;
  }
  if (!reference)
    return marchCells_lanes(f, o, dir, splat(0.0f), t_max, lim, t_offset, active, stats);
  // The seed's way: sphere tracing of repeated(), then the lantern nearest to each hit.
  const MarchHitLanes h = march_lanes(f, o, dir, splat(0.0f), t_max, lim, t_offset, active, stats);
  CellHitLanes out{h.hit, h.t, {}};
  const V3x8 p = o + dir * h.t;
  for (int i = 0; i < LANES; ++i)
    if (lane(h.hit, i)) out.cell[i] = nearestLantern(f, p.lane(i)).cell;
  return out;
}

}  // namespace

void LanternFestivalScene::radiance_packet(const RayPacket& rays, glm::vec3* out,
                                           RayStats& stats) const {
  const M8 valid = rays.valid();
  const V3x8 eye(rays.origin);
  const MarchLimits lim = limits(march_.max_steps, rays.pixel_angle, 0.0f);
  MarchHitLanes water;
  CellHitLanes lantern;
  if (march_.naive) {
    // marchPrimaryNaive: one plain sphere trace of lanterns and lake together.
    const NaiveHitLanes h = marchNaive_lanes(field_, eye, rays.dir, splat(march_.max_dist), true,
                                             lim, splat(lim.t_offset), valid, stats);
    water = MarchHitLanes{h.hit & h.water, h.t};
    lantern = CellHitLanes{h.hit & ~h.water, h.t, {}};
    for (int i = 0; i < LANES; ++i) lantern.cell[i] = h.cell[i];
  } else {
    water =
        marchWater_lanes(field_.lake, rays.origin, rays.dir, march_.max_dist, lim, valid, stats);
    const F8 t_far = select(water.hit, water.t, splat(march_.max_dist));
    lantern = marchLanterns_lanes(field_, march_, reference_march_, eye, rays.dir, t_far, lim,
                                  splat(lim.t_offset), valid, stats);
  }

  const auto water_hit = [&](int i) { return MarchHit{lane(water.hit, i), water.t[i]}; };
  const auto lantern_hit = [&](int i) {
    return CellHit{lane(lantern.hit, i), lantern.t[i], lantern.cell[i]};
  };
  if (march_.hit_mask) {
    for (int i = 0; i < rays.count; ++i) out[i] = hitMask(water_hit(i), lantern_hit(i));
    return;
  }

  // The primary lantern hits' normals (lanternHitNormal) in lanes.
  const M8 on_lantern = valid & lantern.hit;
  V3x8 normal_lanes(glm::vec3(0.0f));
  if (any(on_lantern))
    normal_lanes =
        lanternNormal_lanes(field_.grid, lantern.cell, on_lantern, eye + rays.dir * lantern.t,
                            normalEps_lanes(march_, lantern.t, rays.pixel_angle));
  if (march_.surface != SURFACE_COLOUR) {  // the depth and normal passes
    const M8 on_water = valid & water.hit & ~lantern.hit;
    V3x8 water_normal(glm::vec3(0.0f));
    if (any(on_water))
      water_normal = waterNormal_lanes(field_.lake, rays.origin + rays.dir * water.t,
                                       normalEps_lanes(march_, water.t, rays.pixel_angle));
    for (int i = 0; i < rays.count; ++i)
      out[i] = lane(on_lantern, i)
                   ? surfaceOutput(march_.surface, lantern.t[i], normal_lanes.lane(i))
               : lane(on_water, i) ? surfaceOutput(march_.surface, water.t[i], water_normal.lane(i))
                                   : noSurface(march_.surface);
    return;
  }

  // skySeen in lanes: the sky where the ray hits nothing; below, the blurred sky where the
  // water's reflection hits no lantern.
  const M8 on_sky = valid & ~water.hit & ~lantern.hit;
  V3x8 sky_seen(glm::vec3(0.0f));
  if (any(on_sky)) sky_seen = skyFrom_lanes(sky_, *sky_.environment, rays.dir, on_sky);
  // bounceOffWater in lanes.
  const M8 bounce = valid & water.hit & ~lantern.hit;
  WaterBounce bounces[LANES];
  if (any(bounce)) {
    const V3x8 p = rays.origin + rays.dir * water.t;
    const V3x8 normal =
        waterNormal_lanes(field_.lake, p, normalEps_lanes(march_, water.t, rays.pixel_angle));
    const V3x8 r = rays.dir - normal * (2.0f * vdot(normal, rays.dir));
    const MarchLimits lim_r = limits(march_.reflect_steps, rays.pixel_angle, 0.0f);
    const CellHitLanes h =
        marchLanterns_lanes(field_, march_, reference_march_, p, r, splat(march_.max_dist), lim_r,
                            water.t, bounce, stats);
    const M8 reflects_lantern = bounce & h.hit, reflects_sky = bounce & ~h.hit;
    if (any(reflects_sky))
      sky_seen = select(reflects_sky,
                        skyFrom_lanes(sky_, *sky_.environment_blurred, r, reflects_sky), sky_seen);
    V3x8 hit_normal(glm::vec3(0.0f));
    if (any(reflects_lantern))
      hit_normal = lanternNormal_lanes(field_.grid, h.cell, reflects_lantern, p + r * h.t,
                                       normalEps_lanes(march_, water.t + h.t, rays.pixel_angle));
    for (int i = 0; i < LANES; ++i)
      bounces[i] = WaterBounce{p.lane(i), r.lane(i), CellHit{lane(h.hit, i), h.t[i], h.cell[i]},
                               hit_normal.lane(i)};
  }
  for (int i = 0; i < rays.count; ++i)
    out[i] = shadeHits(rays.ray(i), water_hit(i), lantern_hit(i), normal_lanes.lane(i), bounces[i],
                       sky_seen.lane(i));
}

}  // namespace sdfreel::lantern_festival
