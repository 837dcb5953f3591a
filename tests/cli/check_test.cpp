// `sdfreel check`: validates a timeline as render does (the same message, exit 2) and prints what
// a render would make, the camera path's length and top speed among it, writing nothing.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <utility>

#include "cli/harness.h"

namespace sdfreel::test {
namespace {

namespace fs = std::filesystem;

// 20 frames at 10 fps; the camera moves 10 units in a straight line in 2 s, linearly: 5 units/s.
const char* kTimeline =
    "[video]\nscene = \"sdf_morph\"\nfps = 10\nduration = 2.0\nresolution = [64, 36]\n"
    "samples = 2\n\n[output]\ndir = \"out\"\nframes = [\"png\"]\nvideo = \"v.mkv\"\n"
    "codec = \"ffv1\"\n\n[camera]\ninterpolation = \"linear\"\nkeys = [\n"
    "  { t = 0.0, position = [0.0, 1.0, -5.0], target = [0.0, 0.0, 0.0] },\n"
    "  { t = 2.0, position = [6.0, 1.0, 3.0], target = [0.0, 0.0, 0.0] },\n]\n";

TEST(Check, PrintsWhatARenderWouldMakeAndWritesNothing) {
  const std::string dir = scratch_dir("check-ok");
  write_file(dir + "/t.toml", kTimeline);
  const RunResult r = run_sdfreel("check t.toml", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  for (const char* line :
       {"scene:      sdf_morph\n",
        "frames:     20 at 10/1 fps (2.000 s); this run renders 20 (0-19)\n",
        "picture:    64x36, 2 samples a pixel, quality final\n",
        "camera:     2 keys, linear interpolation; path 10.00 units, top speed 5.00 units/s",
        "output:     out/ (frames/NNNNN.png, frames.framemd5, manifest.json)\n",
        "video:      out/v.mkv (ffv1)\n",
        "geometry:   the camera stays clear of the scene's surfaces (20 frames checked)\n",
        "t.toml: ok, nothing written\n"})
    EXPECT_NE(r.out.find(line), std::string::npos) << "no line " << line << " in:\n" << r.out;
  EXPECT_FALSE(fs::exists(dir + "/out"));

  const RunResult part = run_sdfreel("check t.toml --frames 5-9 --samples 1", dir);
  ASSERT_EQ(part.status, 0) << part.err;
  EXPECT_NE(part.out.find("this run renders 5 (5-9)"), std::string::npos) << part.out;
  EXPECT_NE(part.out.find("1 sample a pixel"), std::string::npos) << part.out;
  EXPECT_NE(part.out.find("video:      none: a partial frame range"), std::string::npos);
}

// The first and last frame of the first run of a warning line ("(frames A-B)" or "(frame A)"),
// or (-1, -1).
std::pair<int, int> first_run(const std::string& line) {
  int a = -1, b = -1;
  const size_t at = line.find("(frame");
  if (at == std::string::npos) return {a, b};
  if (std::sscanf(line.c_str() + at, "(frames %d-%d)", &a, &b) == 2) return {a, b};
  if (std::sscanf(line.c_str() + at, "(frame %d)", &a) == 1) b = a;
  return {a, b};
}

// A path straight through sdf_morph's object (centred at x = z = 0, about 0.7 units high): the
// eye is inside it around t = 1 s (frame 10), and outside at both ends.
TEST(Check, WarnsWhereTheCameraEntersTheScenesGeometry) {
  const std::string dir = scratch_dir("check-inside");
  std::string t = kTimeline;
  t.replace(t.find("[0.0, 1.0, -5.0]"), 16, "[0.0, 0.7, -3.0]");
  t.replace(t.find("[6.0, 1.0, 3.0]"), 15, "[0.0, 0.7, 3.0]");
  for (size_t at; (at = t.find("target = [0.0, 0.0, 0.0]")) != std::string::npos;)
    t.replace(at, 24, "target = [0.0, 0.7, 9.0]");  // looking along the path
  write_file(dir + "/t.toml", t);
  const RunResult r = run_sdfreel("check t.toml", dir);
  ASSERT_EQ(r.status, 0) << r.err;  // a warning, not a refusal
  const size_t at = r.out.find("warning:    the camera is inside the scene's geometry at ");
  ASSERT_NE(at, std::string::npos) << r.out;
  const auto [a, b] = first_run(r.out.substr(at, r.out.find('\n', at) - at));
  EXPECT_TRUE(a > 0 && a <= 10 && b >= 10 && b < 19) << r.out;
  EXPECT_EQ(r.out.find("stays clear"), std::string::npos) << r.out;
  EXPECT_FALSE(fs::exists(dir + "/out"));

  // The frames outside that run are clear: checking them alone warns of nothing.
  const RunResult before = run_sdfreel("check t.toml --frames 0-" + std::to_string(a - 1), dir);
  ASSERT_EQ(before.status, 0) << before.err;
  EXPECT_EQ(before.out.find("warning:    the camera is inside"), std::string::npos) << before.out;
}

// Where a scene cannot tell where its solids are (light_beams is a 2D scene), check says so.
TEST(Check, SaysWhereTheGeometryIsNotChecked) {
  const std::string dir = scratch_dir("check-2d");
  std::string t = kTimeline;
  t.replace(t.find("sdf_morph"), 9, "light_beams");
  write_file(dir + "/t.toml", t);
  const RunResult r = run_sdfreel("check t.toml", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("geometry:   not checked (light_beams cannot tell where its solids are)"),
            std::string::npos)
      << r.out;
}

TEST(Check, RefusesWhatRenderRefusesWithTheSameMessage) {
  const std::string dir = scratch_dir("check-bad");
  write_file(dir + "/t.toml", std::string(kTimeline) + "\n[params]\nmorph_perod = 1.0\n");
  const RunResult check = run_sdfreel("check t.toml", dir);
  const RunResult render = run_sdfreel("render t.toml", dir);
  EXPECT_EQ(check.status, 2);
  EXPECT_EQ(render.status, 2);
  EXPECT_NE(check.err.find("did you mean 'morph_period'"), std::string::npos) << check.err;
  EXPECT_EQ(check.err, render.err);
  EXPECT_TRUE(check.out.empty()) << check.out;
  EXPECT_FALSE(fs::exists(dir + "/out"));
}

}  // namespace
}  // namespace sdfreel::test
