// `render --preview`: the whole timeline, quarter size, one sample, draft, into a folder of its
// own with its video, never over the real render; `--scale` alone; explicit options still win.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "cli/harness.h"

namespace sdfreel::test {
namespace {

namespace fs = std::filesystem;

TEST(Preview, RendersTheWholeTimelineSmallIntoItsOwnFolderWithItsVideo) {
  const std::string dir = scratch_dir("preview");
  // 64x36 at 4 samples, final: the preview is 16x10 (a quarter, to even sides), 1 sample, draft.
  std::string timeline = small_timeline(6, "ffv1", "v.mkv");
  timeline.replace(timeline.find("samples = 1"), 11, "samples = 4");
  timeline.replace(timeline.find("quality = \"draft\""), 17, "quality = \"final\"");
  write_file(dir + "/t.toml", timeline);
  const RunResult r = run_sdfreel("render t.toml --preview", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_FALSE(fs::exists(dir + "/out")) << "the real render's folder is left alone";
  const auto m = nlohmann::json::parse(read_file(dir + "/out-preview/manifest.json"));
  EXPECT_EQ(m.at("resolution"), nlohmann::json::array({16, 10}));
  EXPECT_EQ(m.at("samples"), 1);
  EXPECT_EQ(m.at("quality"), "draft");
  EXPECT_EQ(m.at("frames").size(), 6u);
  EXPECT_TRUE(fs::exists(dir + "/out-preview/v.mkv")) << r.err;

  // Explicit options override the preview's; --scale works alone.
  const RunResult o = run_sdfreel("render t.toml --preview --samples 2 --out p2 --no-video", dir);
  ASSERT_EQ(o.status, 0) << o.err;
  const auto m2 = nlohmann::json::parse(read_file(dir + "/p2/manifest.json"));
  EXPECT_EQ(m2.at("samples"), 2);
  const RunResult s = run_sdfreel("render t.toml --scale 0.5 --out half --no-video", dir);
  ASSERT_EQ(s.status, 0) << s.err;
  const auto m3 = nlohmann::json::parse(read_file(dir + "/half/manifest.json"));
  EXPECT_EQ(m3.at("resolution"), nlohmann::json::array({32, 18}));
  EXPECT_EQ(m3.at("samples"), 4);
  EXPECT_EQ(m3.at("quality"), "final");
}

}  // namespace
}  // namespace sdfreel::test
