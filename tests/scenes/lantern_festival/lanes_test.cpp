// lantern_festival's distance functions in eight lanes give, lane by lane, the bits of the scalar
// functions (one template each): random points near the lanterns and the lake, and far away, at two
// times and two seeds. The marches and normals built on them are checked end to end by
// packet_path_test.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "scenes/lantern_festival/lanes_context.h"
#include "scenes/lantern_festival/march_lanes.h"
#include "scenes/lantern_festival/scene.h"
#include "scenes/registry.h"

namespace sdfreel::lantern_festival {
namespace {

struct Points {
  std::vector<float> x, y, z;
};

// Points around the lake surface and the lanterns (y in -2 .. 3), over a few cells; a share far
// away (the cells the table does not hold) and on cell centre lines.
Points random_points(uint32_t seed, float size) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> near(-3.0f * size, 3.0f * size), height(-2.0f, 3.0f),
      far(-2000.0f, 2000.0f);
  Points p;
  for (int i = 0; i < 4096; ++i) {
    const bool is_far = i % 8 == 7;
    float x = is_far ? far(rng) : near(rng), z = is_far ? far(rng) : near(rng);
    if (i % 16 == 3) x = size * std::round(x / size);  // on a centre line
    p.x.push_back(x);
    p.y.push_back(height(rng));
    p.z.push_back(z);
  }
  return p;
}

int lane_mismatches(const DistanceFunction& f, const Points& p) {
  const int n = int(p.x.size());
  std::vector<float> scalar(n), lanes(n);
  f.scalar(p.x.data(), p.y.data(), p.z.data(), scalar.data(), n);
  f.lanes(p.x.data(), p.y.data(), p.z.data(), lanes.data(), n);
  return n - int(std::count_if(scalar.begin(), scalar.end(), [&](const float& s) {
           return std::memcmp(&s, &lanes[&s - scalar.data()], sizeof s) == 0;
         }));
}

TEST(LanternFestivalLanes, DistanceFunctionsGiveScalarBitsInEveryLane) {
  for (uint64_t seed : {1u, 7u})
    for (double time : {0.0, 4.3}) {
      LanternFestivalScene scene;
      scene.prepare(test::lantern_lanes_context(time, seed));
      const std::vector<DistanceFunction> fns = scene.distance_functions();
      std::set<std::string> names;
      const Points p = random_points(uint32_t(seed * 31 + time * 10), scene.field().grid.size);
      for (const DistanceFunction& f : fns) {
        names.insert(f.name);
        EXPECT_EQ(lane_mismatches(f, p), 0) << f.name << " seed " << seed << " time " << time;
      }
      EXPECT_EQ(names, (std::set<std::string>{"sdfWater", "lanternDistance", "repeated"}));
    }
}

// The distance functions are the scene's own: the named scalar function at the same point.
TEST(LanternFestivalLanes, DistanceFunctionsAreTheScenesFunctions) {
  LanternFestivalScene scene;
  scene.prepare(test::lantern_lanes_context(1.0, 1));
  const LanternField& f = scene.field();
  const Points p = random_points(5, f.grid.size);
  for (const DistanceFunction& fn : scene.distance_functions()) {
    std::vector<float> d(p.x.size());
    fn.lanes(p.x.data(), p.y.data(), p.z.data(), d.data(), int(d.size()));
    for (size_t i = 0; i < d.size(); i += 37) {
      const glm::vec3 q(p.x[i], p.y[i], p.z[i]);
      const float want =
          fn.name == "sdfWater" ? sdfWater(f.lake, q)
          : fn.name == "repeated"
              ? repeated(f, q)
              : lanternDistance(f.grid, f.cell(cellId(f.grid, glm::vec2(q.x, q.z))), q, true);
      EXPECT_EQ(d[i], want) << fn.name << " at point " << i;
    }
  }
}

// The water normal in lanes (tetrahedron taps of the lake) has the scalar normal's bits, including
// the +Y fall-back of safe_normalize.
TEST(LanternFestivalLanes, WaterNormalGivesScalarBits) {
  LanternFestivalScene scene;
  scene.prepare(test::lantern_lanes_context(2.5, 3));
  const LakeFrame& lake = scene.field().lake;
  const Points p = random_points(9, scene.field().grid.size);
  std::mt19937 rng(4);
  std::uniform_real_distribution<float> log_eps(-9.0f, 0.0f);
  int bad = 0;
  for (size_t i = 0; i + LANES <= p.x.size(); i += LANES) {
    const V3x8 q(load8(&p.x[i]), load8(&p.y[i]), load8(&p.z[i]));
    F8 eps;
    for (int k = 0; k < LANES; ++k) eps[k] = k == 0 ? 0.0f : std::exp2(2.0f * log_eps(rng));
    const V3x8 n = waterNormal_lanes(lake, q, eps);
    for (int k = 0; k < LANES; ++k) {
      const glm::vec3 want = waterNormal(lake, q.lane(k), eps[k]);
      const glm::vec3 got = n.lane(k);
      if (std::memcmp(&want, &got, sizeof want) != 0) ++bad;
    }
  }
  EXPECT_EQ(bad, 0);
}

}  // namespace
}  // namespace sdfreel::lantern_festival
