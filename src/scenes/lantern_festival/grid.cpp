#include "scenes/lantern_festival/grid.h"

#include <tbb/parallel_for.h>

namespace sdfreel::lantern_festival {

namespace {

// The exact SDF takes over within this distance (in lantern units) of the bounding cylinder.
constexpr float BOUND_EARLY_OUT = 0.25f;
// A lantern's yaw is free in [0, pi/2): the lantern has four-fold symmetry.
constexpr float YAW_RANGE = dm::HALF_PI;

}  // namespace

GridFrame make_grid_frame(const LakeFrame& lake, float spacing, float jitter, float scale,
                          const Texture& blue_noise) {
  GridFrame g;
  g.scale = scale;
  g.inv_scale = 1.0f / scale;
  // Largest tilt of a lantern: the rough wave's steepest slope.
  const float slope = lake.rough_amp * lake.rough_freq;
  const float sin_tilt = slope / dm::sqrt(1.0f + slope * slope);
  g.bound_radius = scale * (LANTERN_BOUND_RADIUS + LANTERN_BOUND_HALF_HEIGHT * sin_tilt);
  g.bound_half_height = scale * (LANTERN_BOUND_HALF_HEIGHT + LANTERN_BOUND_RADIUS * sin_tilt);
  g.early_out = scale * BOUND_EARLY_OUT;
  // Neighbouring lanterns may touch but never overlap: the 2 x 2 rule needs extent < size.
  g.size = dm::max(spacing, 2.0f * g.bound_radius);
  g.max_offset = dm::clamp(jitter, 0.0f, 1.0f) * dm::max(0.0f, 0.5f * g.size - g.bound_radius);
  g.extent = g.max_offset + g.bound_radius;
  // Lantern centres sit `scale` above the water surface, which lies within -1 +- max_height.
  const float centre_lo = -WATER_PLANE_OFFSET - lake.max_height + scale;
  const float centre_hi = -WATER_PLANE_OFFSET + lake.max_height + scale;
  g.slab_lo = centre_lo - g.bound_half_height;
  g.slab_hi = centre_hi + g.bound_half_height;
  g.blue_noise = &blue_noise;
  return g;
}

LanternCell lanternCellAt(const GridFrame& g, const LakeFrame& lake, const glm::vec2& id) {
  const glm::vec4 bn = blueNoiseAtID(g, id);
  const glm::vec2 centre_xz = id * g.size - offset(g, glm::vec2(bn.x, bn.y));
  LanternCell c;
  // Float on the lake: the base (lantern y = -1) on the water at the centre.
  c.center = glm::vec3(centre_xz.x, waterSurfaceY(lake, centre_xz) + g.scale, centre_xz.y);
  // Tilt: rotate +Y onto the rough wave's normal n (Rodrigues about up x n); the columns of that
  // rotation are X, n, Z below. Then yaw about the lantern's own axis.
  const glm::vec3 n = normalWaterRough(lake, centre_xz);
  const float k = 1.0f / (1.0f + n.y);
  const glm::vec3 X(1.0f - n.x * n.x * k, -n.x, -n.x * n.z * k);
  const glm::vec3 Z(-n.x * n.z * k, -n.z, 1.0f - n.z * n.z * k);
  const float yaw = bn.w * YAW_RANGE;
  const float cy = dm::cos(yaw), sy = dm::sin(yaw);
  // local = rotateY(tilt^T * d, cos yaw, sin yaw), written as three rows.
  c.to_local[0] = X * cy + Z * sy;
  c.to_local[1] = n;
  c.to_local[2] = Z * cy - X * sy;
  c.flicker_phase = bn.z * FLICKER_PERIOD;
  return c;
}

void CellTable::build(const GridFrame& g, const LakeFrame& lake, const glm::vec2& centre_id,
                      int radius) {
  n_ = 2 * radius + 1;
  x0_ = centre_id.x - float(radius);
  z0_ = centre_id.y - float(radius);
  cells_.resize(size_t(n_) * n_);
  // Rows on the threads of the render (prepare() runs under its thread count): each cell is a
  // pure function of its id.
  tbb::parallel_for(0, n_, [&](int z) {
    for (int x = 0; x < n_; ++x)
      cells_[size_t(z) * n_ + x] =
          lanternCellAt(g, lake, glm::vec2(x0_ + float(x), z0_ + float(z)));
  });
}

NearestLantern nearestLantern(const LanternField& f, const glm::vec3& p3) {
  const GridFrame& g = f.grid;
  const glm::vec2 p(p3.x, p3.z);
  const glm::vec2 id = cellId(g, p);
  const glm::vec2 rel = p - g.size * id;
  const glm::vec2 o(neighbourSign(rel.x), neighbourSign(rel.y));
  NearestLantern best{f.cell(id), 1e20f};
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i) {
      const LanternCell c = f.cell(id + glm::vec2(float(i), float(j)) * o);
      const float d = lanternDistance(g, c, p3, true);
      if (d < best.distance) best = NearestLantern{c, d};
    }
  return best;
}

}  // namespace sdfreel::lantern_festival
