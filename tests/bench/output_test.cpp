// bench.csv, the table, the reference cache and the plot file.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "bench/csv.h"
#include "bench/plot.h"
#include "bench/reference_cache.h"
#include "bench/table.h"
#include "io/png_file.h"

namespace sdfreel::bench {
namespace {

std::string temp_dir(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("sdfreel_bench_test_" + name + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir.string();
}

BenchRow row(const std::string& preset, double seconds, double psnr, bool named) {
  BenchRow r;
  r.scene = "sdf_morph";
  r.backend = "cpu";
  r.preset = preset;
  r.named_preset = named;
  r.seconds_per_frame = seconds;
  r.psnr_db = psnr;
  r.rmse = std::pow(10.0, -psnr / 20.0);
  r.samples = 4;
  r.march = march_settings(Quality::Final);
  return r;
}

TEST(Csv, HasTheRequiredColumnsInOrder) {
  const std::vector<std::string> cols = csv_columns();
  const std::vector<std::string> required = {
      "scene", "backend",       "preset",           "seconds_per_frame",  "psnr_db",
      "rmse",  "p99_abs_error", "hitmiss_fraction", "sdf_evals_per_pixel"};
  for (const std::string& r : required)
    EXPECT_NE(std::find(cols.begin(), cols.end(), r), cols.end()) << r;
  EXPECT_EQ(cols[0], "scene");
}

TEST(Csv, RowsRoundTrip) {
  std::vector<BenchRow> rows = {row("final", 0.25, 41.5, true), row("draft", 0.05, 30.0, true)};
  rows[1].psnr_db = std::numeric_limits<double>::infinity();
  rows[0].hitmiss_fraction = 0.125;
  std::ostringstream out;
  write_csv(out, rows);
  std::istringstream in(out.str());
  std::string line;
  std::getline(in, line);
  const std::vector<std::string> header = split_csv_line(line);
  EXPECT_EQ(header, csv_columns());
  const auto col = [&](const std::string& name) {
    return size_t(std::find(header.begin(), header.end(), name) - header.begin());
  };
  std::getline(in, line);
  std::vector<std::string> cells = split_csv_line(line);
  ASSERT_EQ(cells.size(), header.size());
  EXPECT_EQ(cells[col("preset")], "final");
  EXPECT_DOUBLE_EQ(std::stod(cells[col("seconds_per_frame")]), 0.25);
  EXPECT_DOUBLE_EQ(std::stod(cells[col("psnr_db")]), 41.5);
  EXPECT_DOUBLE_EQ(std::stod(cells[col("hitmiss_fraction")]), 0.125);
  std::getline(in, line);
  cells = split_csv_line(line);
  EXPECT_EQ(cells[col("psnr_db")], "inf");
  EXPECT_FALSE(std::getline(in, line));
}

TEST(Table, ShowsPresetsAndFront) {
  std::vector<BenchRow> rows = {row("final", 0.25, 41.5, true),
                                row("final:eps=4", 0.2, 20.0, false),
                                row("final:eps=0.1", 0.3, 45.0, false)};
  rows[2].on_front = true;
  const std::string t = format_table(rows, false);
  EXPECT_NE(t.find("**final**"), std::string::npos);
  EXPECT_NE(t.find("final:eps=0.1"), std::string::npos);
  EXPECT_EQ(t.find("final:eps=4"), std::string::npos);
  EXPECT_NE(format_table(rows, true).find("final:eps=4"), std::string::npos);
}

TEST(ReferenceCache, StoresAndLoadsExactly) {
  const std::string dir = temp_dir("cache");
  const std::string key = reference_key("abc", "samples=64", 5, 3);
  EXPECT_NE(key, reference_key("abd", "samples=64", 5, 3));
  EXPECT_NE(key, reference_key("abc", "samples=32", 5, 3));
  EXPECT_NE(key, reference_key("abc", "samples=64", 3, 5));
  ReferenceCache cache(dir, key);
  ImageRGB16 display(5, 3);
  ImageRGBA mask(5, 3);
  for (size_t i = 0; i < display.pixels.size(); ++i) display.pixels[i] = uint16_t(i * 4099 + 7);
  for (size_t i = 0; i < 15; ++i)
    for (int c = 0; c < 3; ++c) mask.pixels[i * 4 + c] = float(i % 3);
  ImageRGB16 d2;
  ImageRGBA m2;
  EXPECT_FALSE(cache.load(7, 5, 3, d2, m2));
  cache.store(7, display, mask);
  ASSERT_TRUE(cache.load(7, 5, 3, d2, m2));
  EXPECT_EQ(d2.pixels, display.pixels);
  for (size_t i = 0; i < 15; ++i) EXPECT_EQ(m2.pixels[i * 4], mask.pixels[i * 4]);
  EXPECT_FALSE(cache.load(7, 6, 3, d2, m2));  // another size is another reference
  ImageRGBA bad(5, 3);
  bad.pixels[0] = 0.5f;  // not a hit id
  EXPECT_THROW(cache.store(8, display, bad), std::runtime_error);
  std::filesystem::remove_all(dir);
}

TEST(Plot, WritesAPngWithMarksAndText) {
  const std::string dir = temp_dir("plot");
  std::vector<BenchRow> rows = {row("naive", 1.0, 35.0, true), row("draft", 0.02, 28.0, true),
                                row("final", 0.1, 41.0, true)};
  for (BenchRow& r : rows) r.on_front = true;
  const std::string path = dir + "/plot.png";
  plot_speed_error(rows, "test plot", path);
  const PngPixels png = read_png(path, 3);
  EXPECT_GE(png.width, 640);
  EXPECT_GE(png.height, 400);
  std::vector<uint8_t> px(png.samples.size());
  for (size_t i = 0; i < px.size(); ++i) px[i] = uint8_t(png.samples[i] >> 8);
  // Some pixels are the series colour (blue dominant), some are dark (text, axes).
  size_t blue = 0, dark = 0;
  for (size_t i = 0; i + 2 < px.size(); i += 3) {
    if (px[i + 2] > 150 && px[i] < 80) ++blue;
    if (px[i] < 60 && px[i + 1] < 60 && px[i + 2] < 60) ++dark;
  }
  EXPECT_GT(blue, 50u);
  EXPECT_GT(dark, 500u);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace sdfreel::bench
