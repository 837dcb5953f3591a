// The Pareto front of known points, and the presets and sweep the bench measures.
#include "bench/pareto.h"

#include <gtest/gtest.h>

#include <set>

#include "bench/sweep.h"

namespace sdfreel::bench {
namespace {

TEST(Pareto, KnownFront) {
  // (seconds, psnr): a, b, c form the front; d is beaten by b (slower, worse); e by c.
  const std::vector<SpeedError> pts = {
      {0.1, 25.0},  // a: fastest
      {0.3, 35.0},  // b
      {1.0, 45.0},  // c: best
      {0.5, 30.0},  // d: slower and worse than b
      {2.0, 45.0},  // e: as good as c but slower
  };
  EXPECT_EQ(pareto_front(pts), (std::vector<bool>{true, true, true, false, false}));
}

TEST(Pareto, EqualPointsStayOnTheFront) {
  const std::vector<SpeedError> pts = {{1.0, 30.0}, {1.0, 30.0}, {2.0, 20.0}};
  EXPECT_EQ(pareto_front(pts), (std::vector<bool>{true, true, false}));
}

TEST(Pareto, InfinitePsnrDominates) {
  const double inf = std::numeric_limits<double>::infinity();
  const std::vector<SpeedError> pts = {{1.0, inf}, {1.5, 50.0}, {0.5, 20.0}};
  EXPECT_EQ(pareto_front(pts), (std::vector<bool>{true, false, true}));
}

TEST(Sweep, PresetsAreNaiveDraftFinal) {
  const std::vector<BenchConfig> p = preset_configs();
  ASSERT_EQ(p.size(), 3u);
  EXPECT_EQ(p[0].name, "naive");
  EXPECT_TRUE(p[0].march.naive);
  EXPECT_EQ(p[0].march.step_factor, 1.0f);
  EXPECT_EQ(p[1].name, "draft");
  EXPECT_EQ(p[2].name, "final");
  for (const BenchConfig& c : p) EXPECT_TRUE(c.named_preset);
  EXPECT_FALSE(p[1].march.naive);
  EXPECT_FALSE(p[2].march.naive);
  EXPECT_GT(reference_config().samples, p[2].samples);
}

TEST(Sweep, VariesEachMarchParameter) {
  std::set<float> eps, relax;
  std::set<int> steps, samples;
  for (const BenchConfig& c : sweep_configs()) {
    EXPECT_FALSE(c.named_preset) << c.name;
    EXPECT_FALSE(c.march.hit_mask) << c.name;
    eps.insert(c.march.hit_eps);
    relax.insert(c.march.step_factor);
    steps.insert(c.march.max_steps);
    samples.insert(c.samples);
  }
  EXPECT_GE(eps.size(), 4u);
  EXPECT_GE(relax.size(), 3u);
  EXPECT_GE(steps.size(), 4u);
  EXPECT_GE(samples.size(), 3u);
}

TEST(Sweep, SettingsTextSeparatesConfigurations) {
  BenchConfig a = preset_configs()[2];
  BenchConfig b = a;
  EXPECT_TRUE(same_settings(a, b));
  b.march.hit_eps *= 2.0f;
  EXPECT_FALSE(same_settings(a, b));
  b = a;
  b.samples += 1;
  EXPECT_FALSE(same_settings(a, b));
}

}  // namespace
}  // namespace sdfreel::bench
