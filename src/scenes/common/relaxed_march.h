#pragma once
// The relaxed sphere tracing of a scene's march(), one ray and eight lanes (per-lane state frozen
// by masks, the same bits): over-relaxation by omega with its fall-back to a plain step when the
// spheres stop overlapping, a hit epsilon that grows with the pixel footprint, and only a plain
// step may leave at tmax (a relaxed one may have jumped over a surface just in front of it).
// Scenes that march one field this way share it: sdf_morph and water_lily. `map(p)` is the scene's
// distance (and, for one ray, counts its own evaluations).
#include <glm/glm.hpp>

#include "render/rays.h"
#include "sdf/det_math.h"
#include "sdf/lanes.h"

namespace sdfreel {

struct RelaxedMarchSettings {
  int max_steps;
  bool naive;         // plain steps and a fixed world-space epsilon (the bench's baseline)
  float step_factor;  // over-relaxation omega
  float hit_eps;      // naive: world units
  float min_hit_eps;  // floor of the footprint epsilon
  float no_hit;       // t of a miss
};

// t, or s.no_hit for a miss; a ray out of steps counts as a hit where it stopped (stats.capped).
// The footprint epsilon is eps_per_t * (t_before + t): t_before is the path length before ro. An
// eye inside the surface sees d < 0 at once: a hit at tmin.
template <class Map>
float relaxed_march(const Map& map, const glm::vec3& ro, const glm::vec3& rd, float tmin,
                    float tmax, float eps_per_t, float t_before, const RelaxedMarchSettings& s,
                    RayStats& stats) {
  float t = tmin;
  float omega = s.naive ? 1.0f : s.step_factor;
  float prev_d = 0.0f;
  float step = 0.0f;
  for (int i = 0; i < s.max_steps; ++i) {
    stats.steps += 1;
    const float d = map(ro + rd * t);
    if (omega > 1.0f && dm::abs(d) + prev_d < step) {
      t += prev_d - step;  // back to the previous point plus a plain step
      step = prev_d;
      omega = 1.0f;
      continue;
    }
    const float eps = s.naive ? s.hit_eps : dm::max(s.min_hit_eps, eps_per_t * (t_before + t));
    if (d < eps) return t;
    step = d * omega;
    prev_d = d;
    t += step;
    if (t > tmax) {
      if (omega <= 1.0f || t - step + d > tmax) return s.no_hit;
      t += d - step;
      step = d;
      omega = 1.0f;
    }
  }
  stats.capped += 1;
  return t;
}

// The same for the lanes in `active` (no_hit for misses and inactive lanes); lanes out of steps
// count as hits where they stopped. The footprint epsilon is eps_per_t * (t_before + t): t_before
// is the path length before ro (a reflection's primary hit).
template <class Map>
F8 march_lanes(const Map& map, const V3x8& ro, const V3x8& rd, F8 tmin, F8 tmax, M8 active,
               F8 eps_per_t, F8 t_before, const RelaxedMarchSettings& s, RayStats& stats) {
  F8 t = tmin;
  F8 omega = splat(s.naive ? 1.0f : s.step_factor);
  F8 prev_d = splat(0.0f);
  F8 step = splat(0.0f);
  F8 result = splat(s.no_hit);
  for (int i = 0; i < s.max_steps && any(active); ++i) {
    const uint64_t n = count_lanes(active);
    stats.steps += n;
    stats.count_evals(active);
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
