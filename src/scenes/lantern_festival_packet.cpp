// lantern_festival's eight-lane path: the primary marches (lake, lanterns), the water normal, the
// reflection and its march run in lanes; shading runs per lane with the scalar functions. Every
// lane gets radiance()'s bits and stats (tests/scenes/packet_path_test.cpp).
#include "scenes/lantern_festival_march8.h"
#include "scenes/lantern_festival_scene.h"

namespace sdfreel::lantern {

namespace {

// LanternFestivalScene::normalEps in lanes.
F8 normalEps8(const MarchSettings& m, F8 t, float pixel_angle) {
  if (m.naive) return splat(m.normal_eps);
  return dm::max(m.normal_eps * t * pixel_angle, 1e-4f);
}

}  // namespace

void LanternFestivalScene::radiance_packet(const RayPacket& rays, glm::vec3* out,
                                           RayStats& stats) const {
  // The naive and reference marches (marchNaive, march of repeated()) stay scalar.
  if (march_.naive || reference_march_) return Scene::radiance_packet(rays, out, stats);
  const M8 valid = rays.valid();
  const V3x8 eye(rays.origin);
  const MarchLimits lim = limits(march_.max_steps, rays.pixel_angle, 0.0f);
  const MarchHit8 water =
      marchWater8(field_.lake, rays.origin, rays.dir, march_.max_dist, lim, valid, stats);
  const F8 t_far = select(water.hit, water.t, splat(march_.max_dist));
  const CellHit8 lantern = marchCells8(field_, eye, rays.dir, splat(0.0f), t_far, lim,
                                       splat(lim.t_offset), valid, stats);

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
  V3x8 normal8(glm::vec3(0.0f));
  if (any(on_lantern))
    normal8 = lanternNormal8(field_.grid, lantern.cell, on_lantern, eye + rays.dir * lantern.t,
                             normalEps8(march_, lantern.t, rays.pixel_angle));

  // bounceOffWater in lanes.
  const M8 bounce = valid & water.hit & ~lantern.hit;
  WaterBounce bounces[LANES];
  if (any(bounce)) {
    const V3x8 p = rays.origin + rays.dir * water.t;
    const V3x8 normal = waterNormal8(field_.lake, p, normalEps8(march_, water.t, rays.pixel_angle));
    const V3x8 r = rays.dir - normal * (2.0f * vdot(normal, rays.dir));
    const MarchLimits lim_r = limits(march_.reflect_steps, rays.pixel_angle, 0.0f);
    const CellHit8 h = marchCells8(field_, p, r, splat(0.0f), splat(march_.max_dist), lim_r,
                                   water.t, bounce, stats);
    const M8 reflects_lantern = bounce & h.hit;
    V3x8 hit_normal(glm::vec3(0.0f));
    if (any(reflects_lantern))
      hit_normal = lanternNormal8(field_.grid, h.cell, reflects_lantern, p + r * h.t,
                                  normalEps8(march_, water.t + h.t, rays.pixel_angle));
    for (int i = 0; i < LANES; ++i)
      bounces[i] = WaterBounce{p.lane(i), r.lane(i), CellHit{lane(h.hit, i), h.t[i], h.cell[i]},
                               hit_normal.lane(i)};
  }
  for (int i = 0; i < rays.count; ++i)
    out[i] = shadeHits(rays.ray(i), water_hit(i), lantern_hit(i), normal8.lane(i), bounces[i]);
}

}  // namespace sdfreel::lantern
