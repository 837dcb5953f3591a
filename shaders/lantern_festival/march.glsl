// Ray marching for the lantern scene: the twin of src/scenes/lantern_festival/march.{h,cpp}
// (march, marchCells, boundInterval, marchWater and the tetrahedron normals; same names and order
// of operations).
#include "common/frame.glsl"
#include "lantern_festival/grid.glsl"

struct MarchLimits {
  int max_steps;
  float hit_eps;      // at unit distance, in pixel footprints
  float step_factor;  // over-relaxation
  float pixel_angle;
  float t_offset;  // distance already travelled (reflections)
  bool naive;      // MarchSettings::naive: hit_eps is a fixed world-space threshold
};

float eps_at(MarchLimits lim, float t) {
  if (lim.naive) return lim.hit_eps;
  precise float e = lim.hit_eps * (lim.t_offset + t) * lim.pixel_angle;
  return e;
}

struct MarchHit {
  bool hit;
  float t;
};

struct CellHit {
  bool hit;
  float t;
  LanternCell cell;  // the lantern hit
};

const MarchHit NO_MARCH_HIT = MarchHit(false, 0.0);

// [t0, t1] of the ray inside lo <= y <= hi, intersected with [t_min, t_max]; false when empty.
bool clipToSlab(vec3 o, vec3 dir, float lo, float hi, inout float t0, inout float t1) {
  if (dir.y == 0.0) return o.y >= lo && o.y <= hi && t0 <= t1;
  precise float ta = (lo - o.y) / dir.y, tb = (hi - o.y) / dir.y;
  t0 = dm_max(t0, dm_min(ta, tb));
  t1 = dm_min(t1, dm_max(ta, tb));
  return t0 <= t1;
}

const vec3 TETRA[4] = vec3[4](vec3(1.0, -1.0, -1.0), vec3(-1.0, -1.0, 1.0),
                              vec3(-1.0, 1.0, -1.0), vec3(1.0, 1.0, 1.0));

// The distance functions the C++ passes to its sphereTrace template (lambdas).
const int TRACE_CELL = 0;         // one cell's lantern, exact (marchCells)
const int TRACE_FIELD = 1;        // repeated() with bounding cylinders (march)
const int TRACE_NAIVE = 2;        // repeated(), exact (marchNaive)
const int TRACE_NAIVE_WATER = 3;  // min(exact repeated(), sdfWater) (marchNaive with_water)

float traceDistance(int kind, LanternCell cell, vec3 p) {
  if (kind == TRACE_CELL) return lanternDistance(cell, p, true);
  if (kind == TRACE_FIELD) return repeated(p, false);
  precise float lanterns = repeated(p, true);
  return kind == TRACE_NAIVE_WATER ? dm_min(lanterns, sdfWater(p)) : lanterns;
}

// Over-relaxed sphere tracing of traceDistance(kind) on [t0, t1] with at most `budget`
// evaluations (decremented).
MarchHit sphereTrace(int kind, LanternCell cell, vec3 o, vec3 dir, float t0, float t1,
                     MarchLimits lim, inout int budget, inout RayStats stats) {
  precise float t = t0, t_prev = t0, d_prev = 0.0;
  bool relaxed = false;  // was the step that led here over-relaxed?
  while (budget > 0) {
    --budget;
    precise vec3 p = o + dir * t;
    precise float d = traceDistance(kind, cell, p);
    stats.sdf_evals += 1u;
    stats.steps += 1u;
    // A relaxed step is only safe when the unbounding spheres before and after it overlap.
    if (relaxed && (d < 0.0 || d + d_prev < t - t_prev)) {
      t = t_prev + d_prev;
      relaxed = false;
      continue;
    }
    if (d < eps_at(lim, t)) return MarchHit(true, t);
    t_prev = t;
    d_prev = d;
    t += d * lim.step_factor;
    relaxed = lim.step_factor > 1.0;
    if (t > t1) {
      // Only a plain step may end the march: a relaxed one may have jumped over a surface just
      // before t1 (a lantern's base seen down its axis: tests/hard_cases/lantern_festival/ray_along_lantern_axis).
      if (!relaxed || t_prev + d_prev > t1) return NO_MARCH_HIT;
      t = t_prev + d_prev;
      relaxed = false;
    }
  }
  return NO_MARCH_HIT;
}

const float NO_LIMIT = 1e30;
// A ray crosses at most about 2 * max_dist / size cells; this only guards against endless loops.
const int MAX_CELL_VISITS = 4096;

// Lanterns along o + t dir for t in [t_min, t_max]: the seed's sphere tracing of repeated().
MarchHit march(vec3 o, vec3 dir, float t_min, float t_max, MarchLimits lim,
               inout RayStats stats) {
  precise float t0 = t_min, t1 = t_max;
  if (!clipToSlab(o, dir, u_grid.slab_lo, u_grid.slab_hi, t0, t1)) return NO_MARCH_HIT;
  int budget = lim.max_steps;
  MarchHit h = sphereTrace(TRACE_FIELD, NO_CELL, o, dir, t0, t1, lim, budget, stats);
  if (!h.hit && budget <= 0) stats.capped += 1u;
  return h;
}

// The ray's interval inside a lantern's bounding cylinder (vertical axis through c).
bool boundInterval(vec3 c, vec3 o, vec3 dir, out float t0, out float t1) {
  precise float lo = -NO_LIMIT, hi = NO_LIMIT;
  precise float h = u_grid.bound_half_height, r = u_grid.bound_radius;
  if (dir.y != 0.0) {
    precise float ta = (c.y - h - o.y) / dir.y, tb = (c.y + h - o.y) / dir.y;
    lo = dm_min(ta, tb);
    hi = dm_max(ta, tb);
  } else if (abs(o.y - c.y) > h) {
    return false;
  }
  // Circle in xz, from the closest approach (no cancellation for distant cells).
  precise float ox = o.x - c.x, oz = o.z - c.z;
  precise float a = dir.x * dir.x + dir.z * dir.z;
  if (a > 0.0) {
    precise float tm = -(ox * dir.x + oz * dir.z) / a;
    precise float qx = ox + dir.x * tm, qz = oz + dir.z * tm;
    precise float h2 = r * r - (qx * qx + qz * qz);
    if (h2 < 0.0) return false;
    precise float half_ = sqrt(h2 / a);
    lo = dm_max(lo, tm - half_);
    hi = dm_min(hi, tm + half_);
  } else if (ox * ox + oz * oz > r * r) {
    return false;
  }
  t0 = lo;
  t1 = hi;
  return lo <= hi;
}

CellHit marchCells(vec3 o, vec3 dir, float t_min, float t_max, MarchLimits lim,
                   inout RayStats stats) {
  const CellHit none = CellHit(false, 0.0, NO_CELL);
  precise float t0 = t_min, t1 = t_max;
  if (!clipToSlab(o, dir, u_grid.slab_lo, u_grid.slab_hi, t0, t1)) return none;
  precise vec2 start = vec2(o.x + dir.x * t0, o.z + dir.z * t0);
  precise vec2 id = cellId(start);
  precise float sx = dir.x > 0.0 ? 1.0 : -1.0, sz = dir.z > 0.0 ? 1.0 : -1.0;
  int budget = lim.max_steps;
  for (int visit = 0; visit < MAX_CELL_VISITS; ++visit) {
    stats.steps += 1u;
    // Where the ray leaves this cell, recomputed from the id each time (no drift).
    precise float tx = dir.x != 0.0 ? ((id.x + 0.5 * sx) * u_grid.size - o.x) / dir.x : NO_LIMIT;
    precise float tz = dir.z != 0.0 ? ((id.y + 0.5 * sz) * u_grid.size - o.z) / dir.z : NO_LIMIT;
    LanternCell c = fieldCell(id);
    precise float a, b;
    if (boundInterval(c.center, o, dir, a, b)) {
      a = dm_max(a, t0);
      b = dm_min(b, t1);
      if (a <= b) {
        MarchHit h = sphereTrace(TRACE_CELL, c, o, dir, a, b, lim, budget, stats);
        if (h.hit) return CellHit(true, h.t, c);
        if (budget <= 0) {
          stats.capped += 1u;
          return none;
        }
      }
    }
    // The lantern of a cell lies inside it, so cells in ray order give hits in ray order.
    if (dm_min(tx, tz) >= t1) return none;
    if (tx < tz)
      id.x += sx;
    else
      id.y += sz;
  }
  return none;
}

// The naive preset's march: plain sphere tracing (factor 1) of the exact lantern field, and of the
// lake too when `with_water`, over [0, t_max]: no slabs, bounding cylinders or cell walk.
struct NaiveHit {
  bool hit;
  bool water;  // the hit is the lake's (else a lantern's)
  float t;
  LanternCell cell;  // the lantern hit
};

NaiveHit marchNaive(vec3 o, vec3 dir, float t_max, bool with_water, MarchLimits lim,
                    inout RayStats stats) {
  NaiveHit result = NaiveHit(false, false, 0.0, NO_CELL);
  MarchLimits plain = lim;
  plain.step_factor = 1.0;
  int budget = lim.max_steps;
  MarchHit h = sphereTrace(with_water ? TRACE_NAIVE_WATER : TRACE_NAIVE, NO_CELL, o, dir, 0.0,
                           t_max, plain, budget, stats);
  if (!h.hit) {
    if (budget <= 0) stats.capped += 1u;
    return result;
  }
  result.hit = true;
  result.t = h.t;
  precise vec3 p = o + dir * h.t;
  NearestLantern near = nearestLantern(p);
  result.water = with_water && sdfWater(p) < near.distance;
  result.cell = near.cell;
  return result;
}

// The lake along o + t dir for t in [0, t_max].
MarchHit marchWater(vec3 o, vec3 dir, float t_max, MarchLimits lim, inout RayStats stats) {
  precise float top = -WATER_PLANE_OFFSET + u_lake.max_height;
  precise float t = 0.0;
  if (o.y > top) {
    if (dir.y >= 0.0) return NO_MARCH_HIT;
    t = (top - o.y) / dir.y;
  }
  // The vertical gap shrinks at most `rate` per unit of t forwards, `rate_back` backwards.
  precise float slope = u_lake.lipschitz * sqrt(dir.x * dir.x + dir.z * dir.z);
  precise float rate = slope - dir.y, rate_back = slope + dir.y;
  precise float t_prev = t, free_prev = 0.0;
  bool relaxed = false;
  for (int i = 0; i < lim.max_steps; ++i) {
    if (t > t_max) {
      // As in sphereTrace: only a plain step may end the march.
      if (!relaxed || t_prev + free_prev > t_max) return NO_MARCH_HIT;
      t = t_prev + free_prev;
      relaxed = false;
    }
    precise vec3 p = o + dir * t;
    precise float gap = sdfWater(p);
    stats.sdf_evals += 1u;
    stats.steps += 1u;
    // An over-relaxed step is kept only if the free intervals overlap (Keinert et al. 2014).
    if (relaxed && (gap < 0.0 || (rate_back > 0.0 && free_prev + gap / rate_back < t - t_prev))) {
      t = t_prev + free_prev;
      relaxed = false;
      continue;
    }
    if (gap < eps_at(lim, t)) return MarchHit(true, t);
    // Rising out of the wave slab, or never closing the gap: no hit.
    if (rate <= 0.0 || (p.y > top && dir.y >= 0.0)) return NO_MARCH_HIT;
    t_prev = t;
    free_prev = gap / rate;
    t += free_prev * lim.step_factor;
    relaxed = lim.step_factor > 1.0;
  }
  stats.capped += 1u;
  return NO_MARCH_HIT;
}

// Tetrahedron normals (four taps at the vertices of a tetrahedron of size eps).
vec3 lanternNormal(LanternCell c, vec3 p, float eps) {
  precise vec3 n = vec3(0.0);
  for (int i = 0; i < 4; ++i) {
    precise vec3 q = p + TETRA[i] * eps;
    n += TETRA[i] * lanternDistance(c, q, true);
  }
  return safe_normalize(n);
}

vec3 waterNormal(vec3 p, float eps) {
  precise vec3 n = vec3(0.0);
  for (int i = 0; i < 4; ++i) {
    precise vec3 q = p + TETRA[i] * eps;
    n += TETRA[i] * sdfWater(q);
  }
  return safe_normalize(n);
}
