#include "scenes/lantern_festival/march_lanes.h"

namespace sdfreel::lantern_festival {

namespace {

constexpr float NO_LIMIT = 1e30f;
constexpr int MAX_CELL_VISITS = 4096;  // as in lantern_festival/march.cpp

// MarchLimits::eps_at with a per-lane t_offset.
F8 epsAt(const MarchLimits& lim, F8 t_offset, F8 t) {
  if (lim.naive) return splat(lim.hit_eps);
  return lim.hit_eps * (t_offset + t) * lim.pixel_angle;
}

// clipToSlab in lanes: narrows t0/t1; returns the lanes whose interval is not empty.
M8 clipToSlab_lanes(const V3x8& o, const V3x8& dir, float lo, float hi, F8& t0, F8& t1) {
  const M8 flat = dir.y == 0.0f;
  const F8 ta = (lo - o.y) / dir.y, tb = (hi - o.y) / dir.y;
  t0 = select(flat, t0, dm::max(t0, dm::min(ta, tb)));
  t1 = select(flat, t1, dm::min(t1, dm::max(ta, tb)));
  const M8 inside = (o.y >= lo) & (o.y <= hi);
  return select(flat, inside, splat_mask(true)) & (t0 <= t1);
}

// boundInterval in lanes (each lane its own cylinder centre c).
M8 boundInterval_lanes(const GridFrame& g, const V3x8& c, const V3x8& o, const V3x8& dir, F8& t0,
                       F8& t1) {
  const float h = g.bound_half_height, r = g.bound_radius;
  const float r2 = r * r;
  const M8 sloped = dir.y != 0.0f;
  const F8 ta = (c.y - h - o.y) / dir.y, tb = (c.y + h - o.y) / dir.y;
  F8 lo = select(sloped, dm::min(ta, tb), splat(-NO_LIMIT));
  F8 hi = select(sloped, dm::max(ta, tb), splat(NO_LIMIT));
  M8 out = ~sloped & (dm::abs(o.y - c.y) > h);
  const F8 ox = o.x - c.x, oz = o.z - c.z;
  const F8 a = dir.x * dir.x + dir.z * dir.z;
  const M8 across = a > 0.0f;
  const F8 tm = -(ox * dir.x + oz * dir.z) / a;
  const F8 qx = ox + dir.x * tm, qz = oz + dir.z * tm;
  const F8 h2 = r2 - (qx * qx + qz * qz);
  out |= across & (h2 < 0.0f);
  const F8 half = dm::sqrt(h2 / a);
  lo = select(across, dm::max(lo, tm - half), lo);
  hi = select(across, dm::min(hi, tm + half), hi);
  out |= ~across & (ox * ox + oz * oz > r2);
  t0 = lo;
  t1 = hi;
  return ~out & (lo <= hi);
}

// The locals of sphereTrace (lantern_festival/march.cpp), per lane.
struct TraceLanes {
  F8 t, t_prev, d_prev;
  M8 relaxed;  // was the step that led here over-relaxed?
};

struct TraceStepLanes {
  M8 hit;   // d below the hit epsilon at t
  M8 miss;  // a plain step left [.., t1]: no hit in this interval
};

// One iteration of sphereTrace's loop body for the lanes in `st`, d the distance at s.t: the
// relaxed step's fall-back, the hit test, the step and the rule that only a plain step may end
// the interval at t1. Shared by sphereTrace_lanes and the cell walk of marchCells_lanes.
TraceStepLanes traceStep_lanes(TraceLanes& s, F8 d, M8 st, F8 t1, const MarchLimits& lim,
                               F8 t_offset, M8 relax) {
  const M8 reject = st & s.relaxed & ((d < 0.0f) | (d + s.d_prev < s.t - s.t_prev));
  s.t = select(reject, s.t_prev + s.d_prev, s.t);
  s.relaxed &= ~reject;
  const M8 go = st & ~reject;
  const M8 hit = go & (d < epsAt(lim, t_offset, s.t));
  const M8 step = go & ~hit;
  s.t_prev = select(step, s.t, s.t_prev);
  s.d_prev = select(step, d, s.d_prev);
  s.t = select(step, s.t + d * lim.step_factor, s.t);
  s.relaxed = select(step, relax, s.relaxed);
  const M8 over = step & (s.t > t1);
  const M8 miss = over & (~s.relaxed | (s.t_prev + s.d_prev > t1));
  const M8 back = over & ~miss;
  s.t = select(back, s.t_prev + s.d_prev, s.t);
  s.relaxed &= ~back;
  return {hit, miss};
}

// sphereTrace of lantern_festival/march.cpp in lanes, from t0 to t1 per lane. The budget is
// the same in every lane (all start together), so the loop counter stands for it. Adds the
// capped lanes to stats as march() and marchNaive() do (a miss with the budget spent).
template <class Sdf>
MarchHitLanes sphereTrace_lanes(const Sdf& sdf, const V3x8& o, const V3x8& dir, F8 t0, F8 t1,
                                const MarchLimits& lim, F8 t_offset, M8 active, RayStats& stats) {
  MarchHitLanes out{splat_mask(false), splat(0.0f)};
  // Lanes left out keep a finite t, so the field is never evaluated at inf or NaN.
  const F8 start = select(active, t0, splat(0.0f));
  TraceLanes s{start, start, splat(0.0f), splat_mask(false)};
  M8 last = splat_mask(false);
  const M8 relax = splat_mask(lim.step_factor > 1.0f);
  if (lim.max_steps <= 0) last = active;
  for (int i = 0; i < lim.max_steps && any(active); ++i) {
    if (i == lim.max_steps - 1) last = active;  // these spend the budget this step
    const F8 d = sdf(o + dir * s.t);
    const uint64_t n = count_lanes(active);
    stats.count_evals(active);
    stats.steps += n;
    const TraceStepLanes r = traceStep_lanes(s, d, active, t1, lim, t_offset, relax);
    out.hit |= r.hit;
    out.t = select(r.hit, s.t, out.t);  // a hit leaves s.t as it was tested
    active &= ~(r.hit | r.miss);
  }
  stats.capped += count_lanes(last & ~out.hit);
  return out;
}

}  // namespace

MarchHitLanes march_lanes(const LanternField& f, const V3x8& o, const V3x8& dir, F8 t_min, F8 t_max,
                          const MarchLimits& lim, F8 t_offset, M8 active, RayStats& stats) {
  F8 t0 = t_min, t1 = t_max;
  active &= clipToSlab_lanes(o, dir, f.grid.slab_lo, f.grid.slab_hi, t0, t1);
  if (!any(active)) return MarchHitLanes{splat_mask(false), splat(0.0f)};
  return sphereTrace_lanes([&f](const V3x8& p) { return repeated(f, p); }, o, dir, t0, t1, lim,
                           t_offset, active, stats);
}

NaiveHitLanes marchNaive_lanes(const LanternField& f, const V3x8& o, const V3x8& dir, F8 t_max,
                               bool with_water, const MarchLimits& lim, F8 t_offset, M8 active,
                               RayStats& stats) {
  MarchLimits plain = lim;
  plain.step_factor = 1.0f;
  const auto field = [&f, with_water](const V3x8& p) {
    const F8 lanterns = repeated(f, p, true);
    return with_water ? dm::min(lanterns, sdfWater(f.lake, p)) : lanterns;
  };
  const MarchHitLanes h =
      sphereTrace_lanes(field, o, dir, splat(0.0f), t_max, plain, t_offset, active, stats);
  NaiveHitLanes out{h.hit, splat_mask(false), h.t, {}};
  // The lantern nearest to each hit, one lane at a time as in marchNaive.
  const V3x8 p = o + dir * h.t;
  for (int i = 0; i < LANES; ++i) {
    if (!h.hit[i]) continue;
    const glm::vec3 pi = p.lane(i);
    const NearestLantern near = nearestLantern(f, pi);
    out.cell[i] = near.cell;
    if (with_water && sdfWater(f.lake, pi) < near.distance) out.water[i] = -1;
  }
  return out;
}

MarchHitLanes marchWater_lanes(const LakeFrame& lake, const glm::vec3& o, const V3x8& dir,
                               float t_max, const MarchLimits& lim, M8 active, RayStats& stats) {
  MarchHitLanes out{splat_mask(false), splat(0.0f)};
  const float top = -WATER_PLANE_OFFSET + lake.max_height;
  F8 t = splat(0.0f);
  if (o.y > top) {
    active &= ~(dir.y >= 0.0f);
    t = (top - o.y) / dir.y;
  }
  const F8 slope = lake.lipschitz * dm::sqrt(dir.x * dir.x + dir.z * dir.z);
  const F8 rate = slope - dir.y, rate_back = slope + dir.y;
  F8 t_prev = t, free_prev = splat(0.0f);
  M8 relaxed = splat_mask(false);
  const M8 relax = splat_mask(lim.step_factor > 1.0f);
  // Every lane runs iteration i at the same time: the scalar loop counts `continue`s too.
  for (int i = 0; i < lim.max_steps && any(active); ++i) {
    const M8 over = active & (t > t_max);
    const M8 end = over & (~relaxed | (t_prev + free_prev > t_max));
    active &= ~end;
    const M8 back = over & ~end;
    t = select(back, t_prev + free_prev, t);
    relaxed &= ~back;
    const V3x8 p = o + dir * t;
    const F8 gap = sdfWater(lake, p);
    const uint64_t n = count_lanes(active);
    stats.count_evals(active);
    stats.steps += n;
    const M8 reject =
        active & relaxed &
        ((gap < 0.0f) | ((rate_back > 0.0f) & (free_prev + gap / rate_back < t - t_prev)));
    t = select(reject, t_prev + free_prev, t);
    relaxed &= ~reject;
    const M8 go = active & ~reject;
    const M8 hit = go & (gap < epsAt(lim, splat(lim.t_offset), t));
    out.hit |= hit;
    out.t = select(hit, t, out.t);
    const M8 leave = go & ~hit & ((rate <= 0.0f) | ((p.y > top) & (dir.y >= 0.0f)));
    active &= ~(hit | leave);
    const M8 step = go & ~hit & ~leave;
    t_prev = select(step, t, t_prev);
    free_prev = select(step, gap / rate, free_prev);
    t = select(step, t + free_prev * lim.step_factor, t);
    relaxed = select(step, relax, relaxed);
  }
  stats.capped += count_lanes(active);
  return out;
}

CellHitLanes marchCells_lanes(const LanternField& f, const V3x8& o, const V3x8& dir, F8 t_min,
                              F8 t_max, const MarchLimits& lim, F8 t_offset, M8 active,
                              RayStats& stats) {
  CellHitLanes out{splat_mask(false), splat(0.0f), {}};
  const GridFrame& g = f.grid;
  F8 t0 = t_min, t1 = t_max;
  M8 live = active & clipToSlab_lanes(o, dir, g.slab_lo, g.slab_hi, t0, t1);
  if (!any(live)) return out;
  V2x8 id = cellId(g, vec2_of(o.x + dir.x * t0, o.z + dir.z * t0));
  const F8 sx = select(dir.x > 0.0f, splat(1.0f), splat(-1.0f));
  const F8 sz = select(dir.z > 0.0f, splat(1.0f), splat(-1.0f));
  M8 budget = M8{} + lim.max_steps, visits = M8{};
  const M8 relax = splat_mask(lim.step_factor > 1.0f);
  // Per lane: the cell being visited, where the ray leaves it, and the sphere trace inside it.
  // A cell is its index in the frame's table, read by gathers; one outside the table's window
  // (index -1) is computed into out.cell.
  const float* table = f.table.floats();
  M8 cell_index = M8{} - 1;
  V3x8 centre(glm::vec3(0.0f));
  LanternCellLanes cell_lanes{};
  F8 tx{}, tz{};
  M8 tracing = splat_mask(false);
  TraceLanes s{F8{}, F8{}, F8{}, splat_mask(false)};
  F8 b{};  // end of the trace interval in the current cell

  // The end of a visit: stop at t1, else step to the next cell (x or z first, as the scalar DDA).
  const auto next_cell = [&](M8 m) {
    const M8 stop = m & (dm::min(tx, tz) >= t1);
    const M8 go = m & ~stop;
    const M8 x_first = tx < tz;
    id.x = select(go & x_first, id.x + sx, id.x);
    id.y = select(go & ~x_first, id.y + sz, id.y);
    visits -= go;  // masks are -1
    live &= ~(stop | (go & (visits >= MAX_CELL_VISITS)));
  };

  while (any(live)) {
    // Walk the lanes that are between lanterns until each traces one or is done: sphere-trace
    // steps, the expensive part, then run with as many lanes as possible.
    for (M8 need = live & ~tracing; any(need); need = live & ~tracing) {
      stats.steps += count_lanes(need);
      tx = select(need & (dir.x != 0.0f), ((id.x + 0.5f * sx) * g.size - o.x) / dir.x,
                  select(need, splat(NO_LIMIT), tx));
      tz = select(need & (dir.z != 0.0f), ((id.y + 0.5f * sz) * g.size - o.z) / dir.z,
                  select(need, splat(NO_LIMIT), tz));
      // Most cells are skipped by their bound: only the centres go to lanes here, the rotations
      // when a lane enters the cell.
      cell_index = select(need, f.table.index(id), cell_index);
      const M8 in_table = need & (cell_index >= 0), computed = need & ~in_table;
      const M8 at = select(in_table, cell_index * CELL_FLOATS, M8{});
      centre = select(
          in_table, V3x8(gather(table, at), gather(table, at + 1), gather(table, at + 2)), centre);
      if (any(computed))
        for (int i = 0; i < LANES; ++i)
          if (computed[i]) {
            out.cell[i] = f.cell(glm::vec2(id.x[i], id.y[i]));
            centre.set_lane(i, out.cell[i].center);
          }
      F8 a, bb;
      const M8 in_bound = boundInterval_lanes(g, centre, o, dir, a, bb);
      a = dm::max(a, t0);
      bb = dm::min(bb, t1);
      const M8 enter = need & in_bound & (a <= bb);
      const M8 enter_table = enter & (cell_index >= 0);
      if (any(enter_table)) {
        const M8 row = select(enter_table, cell_index * CELL_FLOATS + 3, M8{});
        cell_lanes.center = select(enter_table, centre, cell_lanes.center);
        for (int r = 0; r < 3; ++r)
          cell_lanes.to_local[r] =
              select(enter_table,
                     V3x8(gather(table, row + 3 * r), gather(table, row + 3 * r + 1),
                          gather(table, row + 3 * r + 2)),
                     cell_lanes.to_local[r]);
      }
      if (any(enter & ~enter_table))
        for (int i = 0; i < LANES; ++i)
          if (enter[i] && cell_index[i] < 0) cell_lanes.set_lane(i, out.cell[i]);
      tracing |= enter;
      s.t = select(enter, a, s.t);
      s.t_prev = select(enter, a, s.t_prev);
      s.d_prev = select(enter, splat(0.0f), s.d_prev);
      b = select(enter, bb, b);
      s.relaxed &= ~enter;
      next_cell(need & ~enter);
    }
    // One step of sphereTrace in every tracing lane.
    const M8 tr = live & tracing;
    const M8 spent = tr & (budget <= 0);
    const M8 st = tr & ~spent;
    budget += st;  // masks are -1
    const F8 d = lanternDistance(g, cell_lanes, o + dir * s.t, true);
    const uint64_t n = count_lanes(st);
    stats.count_evals(st);
    stats.steps += n;
    const TraceStepLanes r = traceStep_lanes(s, d, st, b, lim, t_offset, relax);
    out.hit |= r.hit;
    out.t = select(r.hit, s.t, out.t);
    live &= ~r.hit;
    // A trace that ended without a hit: out of budget ends the ray, else on to the next cell.
    const M8 ended = spent | r.miss;
    tracing &= ~ended;
    const M8 capped = ended & (budget <= 0);
    stats.capped += count_lanes(capped);
    live &= ~capped;
    next_cell(ended & ~capped);
  }
  for (int i = 0; i < LANES; ++i)
    if (lane(out.hit, i) && cell_index[i] >= 0) out.cell[i] = f.table.cell(cell_index[i]);
  return out;
}

V3x8 safe_normalize_lanes(const V3x8& v) {
  const F8 len2 = vdot(v, v);
  const V3x8 n = v / dm::sqrt(len2);
  return select(len2 > SAFE_NORMALIZE_MIN_LENGTH2, n, V3x8(glm::vec3(0.0f, 1.0f, 0.0f)));
}

V3x8 waterNormal_lanes(const LakeFrame& lake, const V3x8& p, F8 eps) {
  V3x8 n(glm::vec3(0.0f));
  for (const glm::vec3& k : TETRA) n = n + k * sdfWater(lake, p + k * eps);
  return safe_normalize_lanes(n);
}

V3x8 lanternNormal_lanes(const GridFrame& g, const LanternCell cells[LANES], M8 m, const V3x8& p,
                         F8 eps) {
  LanternCellLanes c{};
  for (int i = 0; i < LANES; ++i)
    if (m[i]) c.set_lane(i, cells[i]);
  V3x8 n(glm::vec3(0.0f));
  for (const glm::vec3& k : TETRA) n = n + k * lanternDistance(g, c, p + k * eps, true);
  return select(m, safe_normalize_lanes(n), V3x8(glm::vec3(0.0f, 1.0f, 0.0f)));
}

}  // namespace sdfreel::lantern_festival
