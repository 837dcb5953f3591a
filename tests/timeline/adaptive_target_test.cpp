// target_db's threshold (render/adaptive_target.h) against the measurements it was fitted to: a
// target within 0.35 dB of what a threshold gave maps to that threshold, so a target of 45 dB on
// the lanterns lands near 45 (the first mapping, 10^(-dB / 20), gave 0.0056 and about 47 dB).
#include "render/adaptive_target.h"

#include <gtest/gtest.h>

namespace sdfreel {
namespace {

struct Measured {
  float threshold;
  double db;
};

// The lanterns at 1280x720, frames 60, 180, 300, final with adaptive 1..16 (docs/performance.md).
const Measured LANTERNS[] = {{0.005f, 47.24}, {0.01f, 46.47}, {0.015f, 45.97}, {0.02f, 45.51},
                             {0.025f, 45.07}, {0.04f, 43.63}, {0.07f, 41.54}};

TEST(AdaptiveTarget, AMeasuredPsnrMapsBackToItsThreshold) {
  for (const Measured& m : LANTERNS) {
    EXPECT_LE(threshold_for_target_db(m.db + 0.35), m.threshold) << m.db << " dB";
    EXPECT_GE(threshold_for_target_db(m.db - 0.35), m.threshold) << m.db << " dB";
  }
}

TEST(AdaptiveTarget, FortyFiveLandsBetweenTheThresholdsThatBracketIt) {
  const float t = threshold_for_target_db(45.0);
  EXPECT_GT(t, 0.02f);   // 45.51 dB
  EXPECT_LT(t, 0.025f);  // 45.07 dB
}

TEST(AdaptiveTarget, HigherTargetsAskForLowerThresholdsDownToZero) {
  float last = threshold_for_target_db(20.0);
  for (double db = 20.5; db <= 48.0; db += 0.5) {
    const float t = threshold_for_target_db(db);
    EXPECT_LT(t, last) << db;
    EXPECT_GT(t, 0.0f) << db;
    last = t;
  }
  // Past the floor no threshold helps: every pixel takes the maximum.
  EXPECT_EQ(threshold_for_target_db(48.5), 0.0f);
  EXPECT_EQ(threshold_for_target_db(120.0), 0.0f);
}

}  // namespace
}  // namespace sdfreel
