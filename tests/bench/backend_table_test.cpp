// The CPU-against-llvmpipe table: pairs rows of the same scene and preset, computes the ratio and
// applies the target (at most half the time, no more error).
#include "bench/backend_table.h"

#include <gtest/gtest.h>

namespace sdfreel::bench {
namespace {

BenchRow row(const std::string& scene, const std::string& backend, const std::string& preset,
             double seconds, double psnr, bool named = true) {
  BenchRow r;
  r.scene = scene;
  r.backend = backend;
  r.preset = preset;
  r.named_preset = named;
  r.seconds_per_frame = seconds;
  r.psnr_db = psnr;
  return r;
}

TEST(BackendTable, PairsEachScenesPresetsAcrossBackends) {
  const std::vector<BenchRow> rows = {
      row("a", "cpu", "final", 0.1, 42.0),
      row("a", "osmesa", "final", 0.25, 42.0),
      row("a", "cpu", "final:eps=0.1", 0.05, 40.0, false),
      row("a", "osmesa", "final:eps=0.1", 0.2, 40.0, false),
      row("b", "cpu", "final", 0.2, 45.0),
      row("b", "osmesa", "final", 0.3, 45.0),
      row("c", "cpu", "final", 0.2, 45.0)};  // no osmesa row: not compared
  const std::vector<BackendComparison> c = compare_backends(rows, "cpu", "osmesa");
  ASSERT_EQ(c.size(), 2u);
  EXPECT_EQ(c[0].scene, "a");
  EXPECT_DOUBLE_EQ(c[0].speedup(), 2.5);
  EXPECT_TRUE(c[0].meets_target());
  EXPECT_EQ(c[1].scene, "b");
  EXPECT_NEAR(c[1].speedup(), 1.5, 1e-12);
  EXPECT_FALSE(c[1].meets_target());
  const std::string table = format_backend_table(c, true);
  EXPECT_NE(table.find("| a | final | 0.1000 | 0.2500 | 2.50x | 42.00 | 42.00 | yes |"),
            std::string::npos)
      << table;
  EXPECT_NE(table.find("**no**"), std::string::npos);
  EXPECT_NE(table.find("| cpu s/frame | osmesa s/frame | osmesa / cpu |"), std::string::npos)
      << table;
}

TEST(BackendTable, PlatformsSideBySideHaveNoTargetColumn) {
  const std::vector<BenchRow> rows = {row("a", "egl", "final", 0.2, 42.0),
                                      row("a", "osmesa", "final", 0.21, 42.0)};
  const std::string table = format_backend_table(compare_backends(rows, "egl", "osmesa"), false);
  EXPECT_NE(table.find("| a | final | 0.2000 | 0.2100 | 1.05x | 42.00 | 42.00 |\n"),
            std::string::npos)
      << table;
  EXPECT_EQ(table.find("2x"), std::string::npos) << table;
}

TEST(BackendTable, MoreErrorOnTheCpuMissesTheTarget) {
  const std::vector<BenchRow> rows = {row("a", "cpu", "final", 0.1, 39.0),
                                      row("a", "osmesa", "final", 0.5, 42.0)};
  const std::vector<BackendComparison> c = compare_backends(rows, "cpu", "osmesa");
  ASSERT_EQ(c.size(), 1u);
  EXPECT_FALSE(c[0].meets_target());
}

}  // namespace
}  // namespace sdfreel::bench
