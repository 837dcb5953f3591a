// `sdfreel map`: a PNG of the camera path over the scene from above and from the side, laid out
// as docs/cli.md says; bad requests exit 2 and write nothing.
#include <gtest/gtest.h>

#include <filesystem>

#include "cli/harness.h"
#include "io/png_file.h"

namespace sdfreel::test {
namespace {

namespace fs = std::filesystem;

const char* kTimeline =
    "[video]\nscene = \"sdf_morph\"\nfps = 10\nduration = 2.0\nresolution = [64, 36]\n\n"
    "[output]\ndir = \"out\"\nframes = [\"png\"]\nvideo = \"\"\n\n"
    "[camera]\nkeys = [\n"
    "  { t = 0.0, position = [0.0, 1.0, -5.0], target = [0.0, 0.7, 0.0] },\n"
    "  { t = 1.0, position = [3.0, 1.2, -1.0], target = [0.0, 0.7, 0.0] },\n"
    "  { t = 2.0, position = [0.0, 1.4, 4.0], target = [0.0, 0.7, 0.0] },\n]\n";

TEST(Map, WritesTheViewsFromAboveAndFromTheSide) {
  const std::string dir = scratch_dir("map-ok");
  write_file(dir + "/t.toml", kTimeline);
  const RunResult r = run_sdfreel("map t.toml -o map.png --width 400", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("wrote map.png: 2 views of the path"), std::string::npos) << r.err;
  const PngPixels png = read_png(dir + "/map.png", 3);
  EXPECT_EQ(png.width, 400 + 2 * 8);
  // Title line, then two views at least 0.35 of the width high, each with its caption.
  EXPECT_GE(png.height, 8 + 13 + 8 + 2 * (140 + 13 + 6 + 8));
  EXPECT_FALSE(fs::exists(dir + "/out"));  // no render folder

  // light_beams' side is its plane edge-on: the view from above alone.
  std::string flat = kTimeline;
  flat.replace(flat.find("sdf_morph"), 9, "light_beams");
  write_file(dir + "/flat.toml", flat);
  const RunResult one = run_sdfreel("map flat.toml -o flat.png --width 400", dir);
  ASSERT_EQ(one.status, 0) << one.err;
  EXPECT_NE(one.err.find("1 view of the path"), std::string::npos) << one.err;
  EXPECT_LT(read_png(dir + "/flat.png", 3).height, png.height);
}

TEST(Map, RefusesWhatItCannotDrawAndWritesNothing) {
  const std::string dir = scratch_dir("map-bad");
  write_file(dir + "/t.toml", kTimeline);
  const RunResult jpg = run_sdfreel("map t.toml -o map.jpg", dir);
  EXPECT_EQ(jpg.status, 2);
  EXPECT_NE(jpg.err.find("must end in .png"), std::string::npos) << jpg.err;
  const RunResult late = run_sdfreel("map t.toml -o map.png --time 5", dir);
  EXPECT_EQ(late.status, 2);
  EXPECT_NE(late.err.find("outside the timeline"), std::string::npos) << late.err;
  const RunResult shader = run_sdfreel(
      "map '" + source_path("tests/golden/shader_ripples/small.toml") + "' -o map.png", dir);
  EXPECT_EQ(shader.status, 2);
  EXPECT_NE(shader.err.find("no scene for a map to show"), std::string::npos) << shader.err;
  EXPECT_FALSE(fs::exists(dir + "/map.png"));
  EXPECT_FALSE(fs::exists(dir + "/map.jpg"));
}

}  // namespace
}  // namespace sdfreel::test
