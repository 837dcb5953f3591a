#pragma once
// The relaxed sphere tracing of a scene's march() for eight lanes (over-relaxation by omega with
// its fall-back to a plain step, a hit epsilon that grows with the pixel footprint, the tmax rule),
// per-lane state frozen by masks. Scenes that march one field this way share it: sdf_morph and
// water_lily. `map(p)` is the scene's distance in lanes.
#include "render/rays.h"
#include "sdf/lanes.h"

namespace sdfreel {

struct MarchLanesSettings {
  int max_steps;
  bool naive;         // plain steps and a fixed world-space epsilon (the bench's baseline)
  float step_factor;  // over-relaxation omega
  float hit_eps;      // naive: world units
  float min_hit_eps;  // floor of the footprint epsilon
  float no_hit;       // t of a miss
};

// t of the lanes in `active` (no_hit for misses and inactive lanes); lanes out of steps count as
// hits where they stopped. The footprint epsilon is eps_per_t * (t_before + t): t_before is the
// path length before ro (a reflection's primary hit).
template <class Map>
F8 march_lanes(const Map& map, const V3x8& ro, const V3x8& rd, F8 tmin, F8 tmax, M8 active,
               F8 eps_per_t, F8 t_before, const MarchLanesSettings& s, RayStats& stats) {
  F8 t = tmin;
  F8 omega = splat(s.naive ? 1.0f : s.step_factor);
  F8 prev_d = splat(0.0f);
  F8 step = splat(0.0f);
  F8 result = splat(s.no_hit);
  for (int i = 0; i < s.max_steps && any(active); ++i) {
    const uint64_t n = count_lanes(active);
    stats.steps += n;
    stats.sdf_evals += n;
    const F8 d = map(ro + rd * t);
    // Back to the previous point plus a plain step (a `continue` of the scalar loop).
    const M8 back = active & (omega > 1.0f) & (dm::abs(d) + prev_d < step);
    t = select(back, t + (prev_d - step), t);
    step = select(back, prev_d, step);
    omega = select(back, splat(1.0f), omega);
    M8 go = active & ~back;
    const F8 eps = s.naive ? splat(s.hit_eps) : dm::max(s.min_hit_eps, eps_per_t * (t_before + t));
    const M8 hit = go & (d < eps);
    result = select(hit, t, result);
    active &= ~hit;
    go &= ~hit;
    const F8 new_step = d * omega;
    step = select(go, new_step, step);
    prev_d = select(go, d, prev_d);
    t = select(go, t + new_step, t);
    const M8 over = go & (t > tmax);
    // Only a plain step may conclude "nothing before tmax".
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

}  // namespace sdfreel
