#include "scenes/lantern_festival/march.h"

namespace sdfreel::lantern_festival {

namespace {

// [t0, t1] of the ray inside lo <= y <= hi, intersected with [t_min, t_max]; false when empty.
bool clipToSlab(const glm::vec3& o, const glm::vec3& dir, float lo, float hi, float& t0,
                float& t1) {
  if (dir.y == 0.0f) return o.y >= lo && o.y <= hi && t0 <= t1;
  const float ta = (lo - o.y) / dir.y, tb = (hi - o.y) / dir.y;
  t0 = dm::max(t0, dm::min(ta, tb));
  t1 = dm::min(t1, dm::max(ta, tb));
  return t0 <= t1;
}

}  // namespace

const glm::vec3 TETRA[4] = {glm::vec3(1.0f, -1.0f, -1.0f), glm::vec3(-1.0f, -1.0f, 1.0f),
                            glm::vec3(-1.0f, 1.0f, -1.0f), glm::vec3(1.0f, 1.0f, 1.0f)};

namespace {

// Over-relaxed sphere tracing of sdf on [t0, t1] with at most `budget` evaluations (decremented).
template <class Sdf>
MarchHit sphereTrace(const Sdf& sdf, const glm::vec3& o, const glm::vec3& dir, float t0, float t1,
                     const MarchLimits& lim, int& budget, RayStats& stats) {
  float t = t0, t_prev = t0, d_prev = 0.0f;
  bool relaxed = false;  // was the step that led here over-relaxed?
  while (budget > 0) {
    --budget;
    const float d = sdf(o + dir * t);
    ++stats.sdf_evals;
    ++stats.steps;
    // A relaxed step is only safe when the unbounding spheres before and after it overlap;
    // otherwise go back to the plain sphere-tracing step from the previous point.
    if (relaxed && (d < 0.0f || d + d_prev < t - t_prev)) {
      t = t_prev + d_prev;
      relaxed = false;
      continue;
    }
    // An eye inside a lantern sees d < 0 at once: a hit at t0
    // (tests/hard_cases/lantern_festival/inside_lantern).
    if (d < lim.eps_at(t)) return {true, t};
    t_prev = t;
    d_prev = d;
    t += d * lim.step_factor;
    relaxed = lim.step_factor > 1.0f;
    if (t > t1) {
      // Only a plain step may end the march: a relaxed one may have jumped over a surface just
      // before t1 (a lantern's base seen down its axis:
      // tests/hard_cases/lantern_festival/ray_along_lantern_axis).
      if (!relaxed || t_prev + d_prev > t1) return {};
      t = t_prev + d_prev;
      relaxed = false;
    }
  }
  return {};
}

constexpr float NO_LIMIT = 1e30f;
// A ray crosses at most about 2 * max_dist / size cells; this only guards against endless loops.
constexpr int MAX_CELL_VISITS = 4096;

}  // namespace

MarchHit march(const LanternField& f, const glm::vec3& o, const glm::vec3& dir, float t_min,
               float t_max, const MarchLimits& lim, RayStats& stats) {
  float t0 = t_min, t1 = t_max;
  if (!clipToSlab(o, dir, f.grid.slab_lo, f.grid.slab_hi, t0, t1)) return {};
  int budget = lim.max_steps;
  const MarchHit h = sphereTrace([&f](const glm::vec3& p) { return repeated(f, p); }, o, dir, t0,
                                 t1, lim, budget, stats);
  if (!h.hit && budget <= 0) ++stats.capped;
  return h;
}

bool boundInterval(const GridFrame& g, const glm::vec3& c, const glm::vec3& o, const glm::vec3& dir,
                   float& t0, float& t1) {
  float lo = -NO_LIMIT, hi = NO_LIMIT;
  const float h = g.bound_half_height, r = g.bound_radius;
  if (dir.y != 0.0f) {
    const float ta = (c.y - h - o.y) / dir.y, tb = (c.y + h - o.y) / dir.y;
    lo = dm::min(ta, tb);
    hi = dm::max(ta, tb);
  } else if (dm::abs(o.y - c.y) > h) {
    return false;
  }
  // Circle in xz, from the closest approach (no cancellation for distant cells:
  // tests/hard_cases/lantern_festival/far_camera_lake). A vertical ray (a = 0) is inside or outside
  // as a whole (tests/hard_cases/lantern_festival/ray_along_lantern_axis).
  const float ox = o.x - c.x, oz = o.z - c.z;
  const float a = dir.x * dir.x + dir.z * dir.z;
  if (a > 0.0f) {
    const float tm = -(ox * dir.x + oz * dir.z) / a;
    const float qx = ox + dir.x * tm, qz = oz + dir.z * tm;
    const float h2 = r * r - (qx * qx + qz * qz);
    if (h2 < 0.0f) return false;
    const float half = dm::sqrt(h2 / a);
    lo = dm::max(lo, tm - half);
    hi = dm::min(hi, tm + half);
  } else if (ox * ox + oz * oz > r * r) {
    return false;
  }
  t0 = lo;
  t1 = hi;
  return lo <= hi;
}

CellHit marchCells(const LanternField& f, const glm::vec3& o, const glm::vec3& dir, float t_min,
                   float t_max, const MarchLimits& lim, RayStats& stats) {
  float t0 = t_min, t1 = t_max;
  if (!clipToSlab(o, dir, f.grid.slab_lo, f.grid.slab_hi, t0, t1)) return {};
  const GridFrame& g = f.grid;
  glm::vec2 id = cellId(g, glm::vec2(o.x + dir.x * t0, o.z + dir.z * t0));
  const float sx = dir.x > 0.0f ? 1.0f : -1.0f, sz = dir.z > 0.0f ? 1.0f : -1.0f;
  int budget = lim.max_steps;
  for (int visit = 0; visit < MAX_CELL_VISITS; ++visit) {
    ++stats.steps;
    // Where the ray leaves this cell (cell borders at (id +- 0.5) * size), recomputed from the id
    // each time rather than accumulated, so no drift over long rays.
    const float tx = dir.x != 0.0f ? ((id.x + 0.5f * sx) * g.size - o.x) / dir.x : NO_LIMIT;
    const float tz = dir.z != 0.0f ? ((id.y + 0.5f * sz) * g.size - o.z) / dir.z : NO_LIMIT;
    const LanternCell c = f.cell(id);
    float a, b;
    if (boundInterval(g, c.center, o, dir, a, b)) {
      a = dm::max(a, t0);
      b = dm::min(b, t1);
      if (a <= b) {
        const MarchHit h =
            sphereTrace([&g, &c](const glm::vec3& p) { return lanternDistance(g, c, p, true); }, o,
                        dir, a, b, lim, budget, stats);
        if (h.hit) return {true, h.t, c};
        if (budget <= 0) {
          ++stats.capped;
          return {};
        }
      }
    }
    // The lantern of a cell lies inside it, so cells in ray order give hits in ray order.
    if (dm::min(tx, tz) >= t1) return {};
    if (tx < tz)
      id.x += sx;
    else
      id.y += sz;
  }
  return {};
}

NaiveHit marchNaive(const LanternField& f, const glm::vec3& o, const glm::vec3& dir, float t_max,
                    bool with_water, const MarchLimits& lim, RayStats& stats) {
  MarchLimits plain = lim;
  plain.step_factor = 1.0f;
  const auto field = [&f, with_water](const glm::vec3& p) {
    const float lanterns = repeated(f, p, true);
    return with_water ? dm::min(lanterns, sdfWater(f.lake, p)) : lanterns;
  };
  int budget = lim.max_steps;
  const MarchHit h = sphereTrace(field, o, dir, 0.0f, t_max, plain, budget, stats);
  if (!h.hit) {
    if (budget <= 0) ++stats.capped;
    return {};
  }
  NaiveHit out;
  out.hit = true;
  out.t = h.t;
  const glm::vec3 p = o + dir * h.t;
  const NearestLantern near = nearestLantern(f, p);
  out.water = with_water && sdfWater(f.lake, p) < near.distance;
  out.cell = near.cell;
  return out;
}

MarchHit marchWater(const LakeFrame& lake, const glm::vec3& o, const glm::vec3& dir, float t_max,
                    const MarchLimits& lim, RayStats& stats) {
  const float top = -WATER_PLANE_OFFSET + lake.max_height;
  float t = 0.0f;
  // An eye at or below the crests starts marching at t = 0, where the gap may be small or
  // negative (a hit at once): tests/hard_cases/lantern_festival/just_above_water, under_water.
  if (o.y > top) {
    if (dir.y >= 0.0f) return {};
    t = (top - o.y) / dir.y;
  }
  // The vertical gap y - surface(x, z) shrinks at most this fast per unit of t forwards, and
  // `rate_back` backwards: each sample's gap frees an interval of the ray on either side.
  const float slope = lake.lipschitz * dm::sqrt(dir.x * dir.x + dir.z * dir.z);
  const float rate = slope - dir.y, rate_back = slope + dir.y;
  float t_prev = t, free_prev = 0.0f;
  bool relaxed = false;
  for (int i = 0; i < lim.max_steps; ++i) {
    if (t > t_max) {
      // As in sphereTrace: only a plain step may end the march.
      if (!relaxed || t_prev + free_prev > t_max) return {};
      t = t_prev + free_prev;
      relaxed = false;
    }
    const glm::vec3 p = o + dir * t;
    const float gap = sdfWater(lake, p);
    ++stats.sdf_evals;
    ++stats.steps;
    // An over-relaxed step is kept only if the free intervals behind this sample and ahead of the
    // previous one overlap (Keinert et al. 2014 for a heightfield); otherwise take the plain step.
    if (relaxed && (gap < 0.0f || (rate_back > 0.0f && free_prev + gap / rate_back < t - t_prev))) {
      t = t_prev + free_prev;
      relaxed = false;
      continue;
    }
    if (gap < lim.eps_at(t)) return {true, t};
    // Rising out of the wave slab, or never closing the gap: no hit (a ray grazing the crests
    // towards the horizon ends here instead of creeping:
    // tests/hard_cases/lantern_festival/horizon_grazing).
    if (rate <= 0.0f || (p.y > top && dir.y >= 0.0f)) return {};
    t_prev = t;
    free_prev = gap / rate;
    t += free_prev * lim.step_factor;
    relaxed = lim.step_factor > 1.0f;
  }
  ++stats.capped;
  return {};
}

glm::vec3 lanternNormal(const GridFrame& g, const LanternCell& c, const glm::vec3& p, float eps) {
  glm::vec3 n(0.0f);
  for (const glm::vec3& k : TETRA) n += k * lanternDistance(g, c, p + k * eps, true);
  return safe_normalize(n);
}

glm::vec3 waterNormal(const LakeFrame& lake, const glm::vec3& p, float eps) {
  glm::vec3 n(0.0f);
  for (const glm::vec3& k : TETRA) n += k * sdfWater(lake, p + k * eps);
  return safe_normalize(n);
}

}  // namespace sdfreel::lantern_festival
