// The night sky in eight lanes (skyFrom_lanes) gives, lane by lane, skyFrom's bits, on both the
// sharp and the blurred environment: random directions of any length, the poles, the horizon, the
// axes (atan2's edges), the zero vector, and a cone round the moon so that the disc's lanes (taken
// one at a time) run too.
#include <gtest/gtest.h>

#include <cstring>
#include <random>
#include <vector>

#include "scenes/lantern_festival/lanes_context.h"
#include "scenes/lantern_festival/scene.h"
#include "scenes/lantern_festival/sky.h"

namespace sdfreel::lantern_festival {
namespace {

bool same_bits(const glm::vec3& a, const glm::vec3& b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

std::vector<glm::vec3> directions(const SkyFrame& s) {
  std::vector<glm::vec3> d = {{0, 1, 0},      {0, -1, 0},     {1, 0, 0},  {-1, 0, 0},
                              {0, 0, 1},      {0, 0, -1},     {0, 0, 0},  {1e-20f, 0, 0},
                              {-1, 0, -0.0f}, {-1, -0.0f, 0}, s.moon_dir, -s.moon_dir};
  std::mt19937 rng(5);
  std::normal_distribution<float> normal;
  std::uniform_real_distribution<float> length(-3.0f, 3.0f), unit(-1.0f, 1.0f);
  for (int i = 0; i < 20000; ++i) {
    const glm::vec3 v(normal(rng), normal(rng), normal(rng));
    d.push_back(v * std::pow(10.0f, length(rng)));
  }
  // Within about 1.5 moon radii of its centre: disc, edge and halo.
  for (int i = 0; i < 4000; ++i)
    d.push_back(s.moon_dir + 0.027f * glm::vec3(unit(rng), unit(rng), unit(rng)));
  while (d.size() % LANES) d.push_back({0, 1, 0});
  return d;
}

TEST(LanternFestivalSkyLanes, EveryLaneGetsTheScalarSkysBits) {
  LanternFestivalScene scene;
  scene.prepare(test::lantern_lanes_context(2.0));
  const SkyFrame& s = scene.sky_frame();
  const std::vector<glm::vec3> d = directions(s);
  int bad = 0, on_disc = 0;
  for (const Texture* env : {s.environment, s.environment_blurred})
    for (size_t i = 0; i < d.size(); i += LANES) {
      V3x8 dir(glm::vec3(0.0f));
      for (int k = 0; k < LANES; ++k) dir.set_lane(k, d[i + k]);
      // Every other packet with one lane off: it may hold anything, the others are unchanged.
      M8 m = splat_mask(true);
      if (i % (2 * LANES) == 0) m[3] = 0;
      const V3x8 lanes = skyFrom_lanes(s, *env, dir, m);
      for (int k = 0; k < LANES; ++k) {
        if (!lane(m, k)) continue;
        if (!same_bits(lanes.lane(k), skyFrom(s, *env, d[i + k]))) ++bad;
        if (glm::dot(glm::normalize(d[i + k]), s.moon_dir) > s.moon_cos_outer) ++on_disc;
      }
    }
  EXPECT_EQ(bad, 0);
  EXPECT_GT(on_disc, 100);  // the disc's lanes were tested
}

}  // namespace
}  // namespace sdfreel::lantern_festival
