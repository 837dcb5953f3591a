// lantern_festival's distance functions for micro-benchmarks and lane tests: the templates of
// lantern_festival/lake.h and lantern_festival/grid.h instantiated for one point and for lanes.
#include "scenes/lantern_festival/scene.h"

namespace sdfreel::lantern_festival {

namespace {

// A DistanceFunction from one template `fn(point)`, scalar and in lanes.
template <class Fn>
DistanceFunction make(const char* name, Fn fn) {
  DistanceFunction d;
  d.name = name;
  d.scalar = [fn](const float* x, const float* y, const float* z, float* out, int n) {
    for (int i = 0; i < n; ++i) out[i] = fn(glm::vec3(x[i], y[i], z[i]));
  };
  d.lanes = [fn](const float* x, const float* y, const float* z, float* out, int n) {
    for (int i = 0; i + LANES <= n; i += LANES)
      store8(out + i, fn(V3x8(load8(x + i), load8(y + i), load8(z + i))));
  };
  return d;
}

}  // namespace

std::vector<DistanceFunction> LanternFestivalScene::distance_functions() const {
  const LanternField* f = &field_;
  return {
      make("sdfWater", [f](const auto& p) { return sdfWater(f->lake, p); }),
      // The exact distance to the lantern of the point's own cell (cellId of p.xz): near that
      // lantern, the distance the cell march traces and the normals differentiate.
      make("lanternDistance",
           [f](const auto& p) {
             return lanternDistance(f->grid, cellAt(*f, cellId(f->grid, vec2_of(p.x, p.z))), p,
                                    true);
           }),
      make("repeated", [f](const auto& p) { return repeated(*f, p); }),
  };
}

std::optional<float> LanternFestivalScene::solid_distance(const glm::vec3& p) const {
  return std::min(sdfWater(field_.lake, p), repeated(field_, p, true));
}

}  // namespace sdfreel::lantern_festival
