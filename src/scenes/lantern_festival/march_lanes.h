#pragma once
// The marches of lantern_festival/march.h for eight rays at once (sdf/lanes.h): each lane performs
// the scalar loop's operations in the same order, so every lane gets the scalar bits and the same
// RayStats. Per-lane state (t, budget, cell, ...) is frozen by masks once a lane is done; the early
// returns of the scalar loops become masks. Lanes outside `active` are not marched or counted.
#include "scenes/lantern_festival/march.h"

namespace sdfreel::lantern_festival {

struct MarchHitLanes {
  M8 hit;
  F8 t;
};

struct CellHitLanes {
  M8 hit;
  F8 t;
  LanternCell cell[LANES];  // the lantern hit, in lanes that hit
};

// marchWater for eight rays from one eye.
MarchHitLanes marchWater_lanes(const LakeFrame& lake, const glm::vec3& o, const V3x8& dir,
                               float t_max, const MarchLimits& lim, M8 active, RayStats& stats);

// marchCells for eight rays with their own origins and march intervals; t_offset replaces
// lim.t_offset per lane (reflections: the distance already travelled).
CellHitLanes marchCells_lanes(const LanternField& f, const V3x8& o, const V3x8& dir, F8 t_min,
                              F8 t_max, const MarchLimits& lim, F8 t_offset, M8 active,
                              RayStats& stats);

// march (the reference preset's sphere tracing of repeated()) for eight rays with their own
// origins and intervals; t_offset as in marchCells_lanes.
MarchHitLanes march_lanes(const LanternField& f, const V3x8& o, const V3x8& dir, F8 t_min, F8 t_max,
                          const MarchLimits& lim, F8 t_offset, M8 active, RayStats& stats);

struct NaiveHitLanes {
  M8 hit, water;
  F8 t;
  LanternCell cell[LANES];  // the nearest lantern, in lanes that hit
};
// marchNaive for eight rays with their own origins; t_offset as in marchCells_lanes.
NaiveHitLanes marchNaive_lanes(const LanternField& f, const V3x8& o, const V3x8& dir, F8 t_max,
                               bool with_water, const MarchLimits& lim, F8 t_offset, M8 active,
                               RayStats& stats);

// safe_normalize and waterNormal in lanes.
V3x8 safe_normalize_lanes(const V3x8& v);
V3x8 waterNormal_lanes(const LakeFrame& lake, const V3x8& p, F8 eps);
// lanternNormal in lanes, each lane at its own lantern; lanes where `m` is clear return +Y.
V3x8 lanternNormal_lanes(const GridFrame& g, const LanternCell cells[LANES], M8 m, const V3x8& p,
                         F8 eps);

}  // namespace sdfreel::lantern_festival
