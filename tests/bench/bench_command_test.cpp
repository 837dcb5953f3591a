// `sdfreel bench` end to end on a tiny frame: the table, bench.csv, the plot, the reference cache
// (rendered once, reused by the next run), and bad usage.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "bench/csv.h"
#include "support/run.h"
#include "support/scratch.h"

namespace sdfreel::bench {
namespace {

TEST(BenchCommand, WritesTableCsvPlotAndReusesTheReference) {
  const std::string dir = test::scratch_dir("bench-command");
  const std::string args =
      "bench sdf_morph --resolution 16x9 --frames 0 --presets-only "
      "--repetitions 1 --out " +
      dir;
  const test::RunResult r = test::run_sdfreel(args);
  ASSERT_EQ(r.status, 0) << r.out;
  for (const char* preset : {"**naive**", "**draft**", "**final**"})
    EXPECT_NE(r.out.find(preset), std::string::npos) << r.out;
  EXPECT_TRUE(std::filesystem::exists(dir + "/bench_sdf_morph.png"));
  std::ifstream csv(dir + "/bench.csv");
  std::string line;
  ASSERT_TRUE(std::getline(csv, line));
  EXPECT_EQ(split_csv_line(line), csv_columns());
  int rows = 0;
  while (std::getline(csv, line)) {
    EXPECT_EQ(split_csv_line(line).size(), csv_columns().size()) << line;
    ++rows;
  }
  EXPECT_EQ(rows, 3);
  // One reference folder, with the frame and its hit mask; a second run adds none.
  const auto ref_root = std::filesystem::path(dir) / "reference";
  auto count = [&] {
    return std::distance(std::filesystem::directory_iterator(ref_root),
                         std::filesystem::directory_iterator());
  };
  ASSERT_EQ(count(), 1);
  const auto folder = std::filesystem::directory_iterator(ref_root)->path();
  EXPECT_TRUE(std::filesystem::exists(folder / "00000.png"));
  EXPECT_TRUE(std::filesystem::exists(folder / "00000.mask.png"));
  const auto stamp = std::filesystem::last_write_time(folder / "00000.png");
  ASSERT_EQ(test::run_sdfreel(args).status, 0);
  EXPECT_EQ(count(), 1);
  EXPECT_EQ(std::filesystem::last_write_time(folder / "00000.png"), stamp);
  std::filesystem::remove_all(dir);
}

TEST(BenchCommand, BadUsageExitsWithTwo) {
  const std::string dir = test::scratch_dir("bench-command-usage");
  EXPECT_EQ(test::run_sdfreel("bench no_such_scene --out " + dir).status, 2);
  EXPECT_EQ(test::run_sdfreel("bench sdf_morph --resolution 16by9 --out " + dir).status, 2);
  EXPECT_EQ(test::run_sdfreel("bench sdf_morph --frames 999999 --out " + dir).status, 2);
  EXPECT_EQ(test::run_sdfreel("bench --out " + dir).status, 2);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace sdfreel::bench
