// The bench's `final` is what a `final` timeline's `adaptive = true` does at the bench's size:
// adaptive 4..28 on small frames (render/quality.h), fixed 16 samples otherwise; the sweep varies
// the fixed one at every size.
#include <gtest/gtest.h>

#include "bench/sweep.h"
#include "render/adaptive_sampling.h"

namespace sdfreel::bench {
namespace {

TEST(BenchPresets, FinalOnASmallFrameIsTheAdaptivePreset) {
  const std::vector<BenchConfig> small = preset_configs(160, 90);
  ASSERT_EQ(small.back().name, "final");
  EXPECT_TRUE(small.back().adaptive.enabled);
  EXPECT_EQ(small.back().adaptive.minimum, 4);
  EXPECT_EQ(small.back().adaptive.maximum, 28);
  EXPECT_EQ(small.back().adaptive.threshold, 0.008f);
  EXPECT_EQ(small.back().march.max_steps, march_settings(Quality::Final).max_steps);
  const std::vector<BenchConfig> ordinary = preset_configs(320, 180);
  ASSERT_EQ(ordinary.back().name, "final");
  EXPECT_FALSE(ordinary.back().adaptive.enabled);
  EXPECT_EQ(ordinary.back().samples, 16);
  for (const BenchConfig& c : sweep_configs())
    if (c.name.rfind("final:spp=", 0) == 0) {
      EXPECT_FALSE(c.adaptive.enabled) << c.name;
    }
}

// Where `final` is adaptive, the fixed 16 samples are still measured, under the name that says so.
TEST(BenchPresets, TheSweepHoldsTheFixedFinalOnceAsItsSampleCount) {
  const BenchConfig fixed_final = preset_configs()[2];
  std::vector<std::string> same;
  for (const BenchConfig& c : sweep_configs())
    if (same_settings(c, fixed_final)) same.push_back(c.name);
  ASSERT_EQ(same.size(), 1u);
  EXPECT_EQ(same[0], "final:spp=16");
}

}  // namespace
}  // namespace sdfreel::bench
