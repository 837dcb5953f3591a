// Adaptive bench points by name: every sweep point's name gives back its settings, and `--only`
// may name points outside the sweep; malformed or out-of-range names are not points.
#include "bench/adaptive_configs.h"

#include <gtest/gtest.h>

namespace sdfreel::bench {
namespace {

TEST(AdaptiveConfigs, EverySweepNameGivesItsSettingsBack) {
  for (const BenchConfig& c : adaptive_configs()) {
    const std::optional<BenchConfig> named = adaptive_config_named(c.name);
    ASSERT_TRUE(named) << c.name;
    EXPECT_EQ(named->name, c.name);
    EXPECT_TRUE(same_settings(*named, c)) << c.name;
  }
}

TEST(AdaptiveConfigs, NamesAPointOutsideTheSweep) {
  const std::optional<BenchConfig> c = adaptive_config_named("final:adaptive=0.004/2-64");
  ASSERT_TRUE(c);
  EXPECT_TRUE(c->adaptive.enabled);
  EXPECT_EQ(c->adaptive.minimum, 2);
  EXPECT_EQ(c->adaptive.maximum, 64);
  EXPECT_EQ(c->adaptive.threshold, 0.004f);
  EXPECT_EQ(c->quality, Quality::Final);
  EXPECT_EQ(c->name, "final:adaptive=0.004/2-64");
}

TEST(AdaptiveConfigs, RefusesMalformedAndOutOfRangeNames) {
  for (const char* bad :
       {"final:adaptive=", "final:adaptive=0.01", "final:adaptive=0.01/2", "final:adaptive=0.01/2-",
        "final:adaptive=0.01/2-16x", "final:adaptive=x/2-16", "final:adaptive=0.01/0-16",
        "final:adaptive=0.01/8-4", "final:adaptive=0.01/1-1025", "final:adaptive=1.5/1-16",
        "final:adaptive=-0.1/1-16", "draft:adaptive=0.01/1-16", "final:spp=4"})
    EXPECT_FALSE(adaptive_config_named(bad)) << bad;
}

}  // namespace
}  // namespace sdfreel::bench
