#pragma once
// The unbounded, irregular grid of lanterns (seed 000, "Irregular repetition"). Cell `id` (a pair
// of integers, kept as floats like the seed's round(p / gridSize)) holds one lantern, moved off
// the cell centre by a blue-noise offset, floated on the lake and tilted with the rough wave.
//
// repeated() evaluates the 2 x 2 cells nearest to p (Quilez, "domain repetition", the rule for
// shapes that differ per cell) and adds what the rule needs to be a true distance bound: every
// lantern stays inside a square of half size `extent` < cell size around its grid point, so the
// lanterns of all other cells are at least min(q.x, q.z) + size - extent away (q: p relative to
// its cell centre, folded towards the checked neighbours). With that cap no lantern is ever
// missed or cut at a cell border, and the field is continuous there.
#include <glm/glm.hpp>
#include <vector>

#include "scenes/common/texture.h"
#include "scenes/lantern_festival/lake.h"
#include "scenes/lantern_festival/lantern.h"

namespace sdfreel::lantern_festival {

// The seed's flicker is periodic: cos(2 pi T), cos(3 pi T) and cos(2.5 pi T) all repeat after 4.
constexpr float FLICKER_PERIOD = 4.0f;

// Per-frame constants of the grid.
struct GridFrame {
  float size = 8.0f;        // cell spacing (world units)
  float max_offset = 0.0f;  // |blue-noise offset| per axis
  float scale = 1.0f;       // lantern size
  float inv_scale = 1.0f;
  float bound_radius = 0.0f;       // world bounding cylinder around a lantern's centre,
  float bound_half_height = 0.0f;  // tilt included
  float early_out = 0.0f;          // farther than this from the bound, the bound is the distance
  float extent = 0.0f;             // max-norm reach of a lantern from its grid point
  float slab_lo = 0.0f, slab_hi = 0.0f;  // world y range that holds every lantern
  const Texture* blue_noise = nullptr;
};

// spacing and jitter (0..1: share of the free room a lantern may move) from the parameters.
GridFrame make_grid_frame(const LakeFrame& lake, float spacing, float jitter, float scale,
                          const Texture& blue_noise);

// Per-cell constants: computed once per cell and frame (see CellTable), never per march step.
struct LanternCell {
  glm::vec3 center;       // world position of the lantern's origin
  glm::vec3 to_local[3];  // rows of the world -> lantern rotation (yaw, then the wave's tilt)
  float flicker_phase;    // added to the flicker clock so that lanterns do not pulse in unison
};
constexpr int CELL_FLOATS = 13;  // a LanternCell is these floats, in this order
static_assert(sizeof(LanternCell) == CELL_FLOATS * sizeof(float));

inline glm::vec4 blueNoiseAtID(const GridFrame& g, const glm::vec2& id) {
  return texelFetchRepeat(*g.blue_noise, id.x, id.y);
}

// The seed's offset(blueNoise.xy): centred, scaled to the free room of the cell.
inline glm::vec2 offset(const GridFrame& g, const glm::vec2& bn) {
  return (bn * 2.0f - 1.0f) * g.max_offset;
}

LanternCell lanternCellAt(const GridFrame& g, const LakeFrame& lake, const glm::vec2& id);

// Eight lanes' cells (each lane may be in another cell): the lane twin of LanternCell.
struct LanternCellLanes {
  V3x8 center;
  V3x8 to_local[3];
  void set_lane(int i, const LanternCell& c) {
    center.set_lane(i, c.center);
    for (int r = 0; r < 3; ++r) to_local[r].set_lane(i, c.to_local[r]);
  }
};

// Templates over the cell and point types (LanternCell and glm::vec3, or LanternCellLanes and
// V3x8).
template <class Cell, class V>
inline V toLocal(const Cell& c, const V& d) {
  return vec3_of(vdot(c.to_local[0], d), vdot(c.to_local[1], d), vdot(c.to_local[2], d));
}
inline glm::vec3 toWorld(const LanternCell& c, const glm::vec3& v) {
  return c.to_local[0] * v.x + c.to_local[1] * v.y + c.to_local[2] * v.z;
}

// Cell data of a window of cells around the camera, filled in prepare(); cells outside the
// window are computed on demand (identical values: same function).
class CellTable {
 public:
  void build(const GridFrame& g, const LakeFrame& lake, const glm::vec2& centre_id, int radius);
  LanternCell at(const GridFrame& g, const LakeFrame& lake, const glm::vec2& id) const {
    const float x = id.x - x0_, z = id.y - z0_;
    if (x >= 0.0f && z >= 0.0f && x < float(n_) && z < float(n_))
      return cells_[size_t(z) * n_ + size_t(x)];
    return lanternCellAt(g, lake, id);
  }
  // In lanes: each lane's index into the window (-1 outside it, where at() computes the cell).
  M8 index(const V2x8& id) const {
    const F8 x = id.x - x0_, z = id.y - z0_;
    const M8 inside = (x >= 0.0f) & (z >= 0.0f) & (x < float(n_)) & (z < float(n_));
    const M8 xi = __builtin_convertvector(select(inside, x, splat(0.0f)), M8);
    const M8 zi = __builtin_convertvector(select(inside, z, splat(0.0f)), M8);
    return select(inside, zi * n_ + xi, M8{} - 1);
  }
  const LanternCell& cell(int index) const { return cells_[size_t(index)]; }
  // The cells' floats, CELL_FLOATS a cell in LanternCell's order, for gathers.
  // (A gather reads every lane: an empty table reads a cell of zeros.)
  const float* floats() const {
    static const LanternCell none{};
    return cells_.empty() ? &none.center.x : &cells_[0].center.x;
  }

 private:
  float x0_ = 0.0f, z0_ = 0.0f;
  int n_ = 0;
  std::vector<LanternCell> cells_;
};

struct LanternField {
  GridFrame grid;
  LakeFrame lake;
  CellTable table;
  LanternCell cell(const glm::vec2& id) const { return table.at(grid, lake, id); }
};

// The seed's round(): floor(x + 0.5), since GLSL leaves round(0.5) to the implementation.
template <class V2>
inline V2 cellId(const GridFrame& g, const V2& p) {
  return vec2_of(dm::floor(p.x / g.size + 0.5f), dm::floor(p.y / g.size + 0.5f));
}

// One lantern's distance. Far from its bounding cylinder the cylinder's distance stands in (a
// lower bound, since the lantern is inside); `exact` turns that off (tests, normals).
// In lanes the bound is taken per lane (select); the lanes skip the lantern only when all can.
template <class Cell, class V>
inline auto lanternDistance(const GridFrame& g, const Cell& c, const V& p, bool exact) {
  const V d = p - c.center;
  if (exact) return sdfLantern(toLocal(c, d) * g.inv_scale) * g.scale;
  const auto bound = sdCappedCylinder(d, g.bound_half_height, g.bound_radius);
  const auto far = bound > g.early_out;
  if (all(far)) return bound;
  return select(far, bound, sdfLantern(toLocal(c, d) * g.inv_scale) * g.scale);
}

// The 2 x 2 neighbour order (tests/hard_cases/lantern_festival/cell_centre_rays): sign() with
// sign(0) = +1, so that a point exactly on a cell's centre line still looks at two distinct columns
// instead of the same one twice.
inline float neighbourSign(float x) {
  return x < 0.0f ? -1.0f : 1.0f;
}
inline F8 neighbourSign(F8 x) {
  return select(x < 0.0f, splat(-1.0f), splat(1.0f));
}

// The cell of `id`, one lane at a time for lanes (each lane looks its own cell up).
inline LanternCell cellAt(const LanternField& f, const glm::vec2& id) {
  return f.cell(id);
}
inline LanternCellLanes cellAt(const LanternField& f, const V2x8& id) {
  LanternCellLanes c;
  for (int i = 0; i < LANES; ++i) c.set_lane(i, f.cell(glm::vec2(id.x[i], id.y[i])));
  return c;
}

// The seed's loop: the lanterns of the 2 x 2 cells nearest to p (glm::vec3 or V3x8).
template <class V>
inline auto nearestFour(const LanternField& f, const V& p3, bool exact) {
  const GridFrame& g = f.grid;
  const auto p = vec2_of(p3.x, p3.z);
  const auto id = cellId(g, p);
  // Neighbour offset direction: towards the nearer border in x and in z.
  const auto o = vec2_of(neighbourSign(p.x - g.size * id.x), neighbourSign(p.y - g.size * id.y));
  auto d = decltype(p3.x){} + 1e20f;
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i) {
      const auto rid = vec2_of(id.x + float(i) * o.x, id.y + float(j) * o.y);
      d = dm::min(d, lanternDistance(g, cellAt(f, rid), p3, exact));
    }
  return d;
}
// Lower bound of the distance to the lanterns of every other cell.
template <class V>
inline auto othersBound(const GridFrame& g, const V& p3) {
  const auto p = vec2_of(p3.x, p3.z);
  const auto id = cellId(g, p);
  const auto rel = vec2_of(p.x - g.size * id.x, p.y - g.size * id.y);
  // Every unchecked cell lies behind p (against o) or two cells ahead; its lantern keeps within
  // `extent` of its grid point, so it is at least |rel| + size - extent away along that axis.
  return dm::min(dm::abs(rel.x), dm::abs(rel.y)) + g.size - g.extent;
}
// The lantern field: min(nearestFour, othersBound), a distance bound with no gaps or jumps.
template <class V>
inline auto repeated(const LanternField& f, const V& p3, bool exact = false) {
  return dm::min(nearestFour(f, p3, exact), othersBound(f.grid, p3));
}

// The lantern nearest to p among the 2 x 2 candidate cells, by exact distance (for shading).
struct NearestLantern {
  LanternCell cell;
  float distance;
};
NearestLantern nearestLantern(const LanternField& f, const glm::vec3& p3);

}  // namespace sdfreel::lantern_festival
