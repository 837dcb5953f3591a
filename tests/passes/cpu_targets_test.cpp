// CpuTargets: what the clear before each sample resets and what it leaves.
#include "backends/cpu/cpu_targets.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace sdfreel {
namespace {

bool all_equal(const ImageRGBA& img, float v) {
  for (float p : img.pixels)
    if (p != v) return false;
  return !img.pixels.empty();
}

TEST(CpuTargets, PerSampleClearLeavesPerFrameAndSkippedTargets) {
  const std::vector<TargetSpec> specs = {
      {"colour", TargetKind::Colour, glm::vec4(0.25f)},
      {"depth", TargetKind::Depth},
      {"counts", TargetKind::Colour},
      {"setup", TargetKind::Colour, glm::vec4(0.0f), glm::ivec2(0), true}};
  CpuTargets t(specs, 3, 2);
  t.clear();
  EXPECT_TRUE(all_equal(t.get("colour", "test"), 0.25f));
  EXPECT_TRUE(all_equal(t.get("depth", "test"), 1.0f));
  EXPECT_TRUE(all_equal(t.get("counts", "test"), 0.0f));
  auto fill = [&](float v) {
    for (const TargetSpec& s : specs)
      for (float& p : t.get(s.name, "test").pixels) p = v;
  };
  fill(7.0f);
  t.skip_per_sample_clear("counts");
  t.clear_per_sample();
  EXPECT_TRUE(all_equal(t.get("colour", "test"), 0.25f));
  EXPECT_TRUE(all_equal(t.get("depth", "test"), 1.0f));
  EXPECT_TRUE(all_equal(t.get("counts", "test"), 7.0f)) << "skipped";
  EXPECT_TRUE(all_equal(t.get("setup", "test"), 7.0f)) << "per frame";
  t.clear();  // the frame's clear still resets every target
  EXPECT_TRUE(all_equal(t.get("counts", "test"), 0.0f));
  EXPECT_TRUE(all_equal(t.get("setup", "test"), 0.0f));
}

}  // namespace
}  // namespace sdfreel
