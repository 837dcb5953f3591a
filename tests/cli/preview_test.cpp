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

// --fps and --duration replace the timeline's: frame i is video time i / fps, the picture `still`
// makes of the timeline at that time; the manifest records the new rate and count.
TEST(Preview, FpsAndDurationOverrideTheTimelines) {
  const std::string dir = scratch_dir("preview-fps");
  write_file(dir + "/t.toml", small_timeline(20, "ffv1", "v.mkv"));  // 10 fps, 2 s
  const RunResult r = run_sdfreel("render t.toml --fps 5 --duration 1.2 --out o", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  const auto m = nlohmann::json::parse(read_file(dir + "/o/manifest.json"));
  EXPECT_EQ(m.at("fps"), "5/1");
  EXPECT_EQ(m.at("frames").size(), 6u);  // 1.2 s at 5 fps
  EXPECT_TRUE(fs::exists(dir + "/o/v.mkv")) << "the whole (overridden) timeline: its video";
  // Frame 3 of the 5 fps render is t = 0.6 s: frame 6 of the 10 fps timeline.
  const RunResult s = run_sdfreel("still t.toml --time 0.6 -o still.png", dir);
  ASSERT_EQ(s.status, 0) << s.err;
  EXPECT_EQ(read_file(dir + "/still.png"), read_file(dir + "/o/frames/00003.png"));

  for (const char* bad :
       {"--fps 0", "--fps 30/0", "--fps fast", "--duration -1", "--duration 1e12"})
    EXPECT_EQ(run_sdfreel(std::string("render t.toml --out bad ") + bad, dir).status, 2) << bad;
  EXPECT_FALSE(fs::exists(dir + "/bad"));
}

// --time-range A-B renders the frames whose time lies in [A, B], as --frames would by number.
TEST(Preview, TimeRangeSelectsFramesBySeconds) {
  const std::string dir = scratch_dir("preview-range");
  write_file(dir + "/t.toml", small_timeline(20, "ffv1", ""));  // 10 fps, frames 0..19
  const RunResult r = run_sdfreel("check t.toml --time-range 0.5-1", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("this run renders 6 (5-10)"), std::string::npos) << r.out;
  const RunResult tail = run_sdfreel("check t.toml --time-range 1.75-9", dir);
  ASSERT_EQ(tail.status, 0) << tail.err;
  EXPECT_NE(tail.out.find("this run renders 2 (18-19)"), std::string::npos) << tail.out;

  const RunResult both = run_sdfreel("render t.toml --time-range 0-1 --frames 0-3", dir);
  EXPECT_EQ(both.status, 2);
  EXPECT_NE(both.err.find("give one of them"), std::string::npos) << both.err;
  for (const char* bad : {"3-4", "1-0.5", "x-1", "1"})
    EXPECT_EQ(run_sdfreel(std::string("render t.toml --time-range ") + bad, dir).status, 2) << bad;
  EXPECT_FALSE(fs::exists(dir + "/out"));
}

// A partial range writes no video unless --video names one: then a video of just those frames,
// in the folder under that name, while the timeline's own video is not made.
TEST(Preview, VideoNamesAVideoOfAPartialRange) {
  const std::string dir = scratch_dir("preview-video");
  write_file(dir + "/t.toml", small_timeline(20, "h264", "v.mp4"));  // 10 fps, frames 0..19
  const RunResult plain = run_sdfreel("render t.toml --time-range 0.5-1 --out a", dir);
  ASSERT_EQ(plain.status, 0) << plain.err;
  EXPECT_FALSE(fs::exists(dir + "/a/v.mp4"));
  EXPECT_NE(plain.err.find("no video (a partial frame range)"), std::string::npos) << plain.err;

  const RunResult r = run_sdfreel("render t.toml --time-range 0.5-1 --video clip.mp4 --out b", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(fs::exists(dir + "/b/clip.mp4")) << r.err;
  EXPECT_FALSE(fs::exists(dir + "/b/v.mp4"));
  const auto m = nlohmann::json::parse(read_file(dir + "/b/manifest.json"));
  EXPECT_EQ(m.at("frames").size(), 6u);
  if (have_tool("ffprobe")) {
    const RunResult p =
        run("ffprobe -v error -count_frames -select_streams v:0 -show_entries "
            "stream=codec_name,nb_read_frames -of csv=p=0 b/clip.mp4",
            dir);
    EXPECT_EQ(p.out, "h264,6\n") << p.err;
  }
  const RunResult c = run_sdfreel("check t.toml --time-range 0.5-1 --video clip.mp4", dir);
  EXPECT_NE(c.out.find("video:      out/clip.mp4 (h264, crf 18)"), std::string::npos) << c.out;
  // .mkv holds ffv1 (its usual codec) and the timeline's h264 alike: say which, as encode does.
  const RunResult both = run_sdfreel("render t.toml --video clip.mkv --out bad", dir);
  EXPECT_EQ(both.status, 2);
  EXPECT_NE(both.err.find("set [output] codec"), std::string::npos) << both.err;

  for (const char* bad : {"--video x.avi", "--video sub/clip.mkv", "--video c.mp4 --no-video"})
    EXPECT_EQ(run_sdfreel(std::string("render t.toml --out bad ") + bad, dir).status, 2) << bad;
  EXPECT_FALSE(fs::exists(dir + "/bad"));
}

}  // namespace
}  // namespace sdfreel::test
