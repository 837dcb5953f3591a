// The h264 video carries BT.709 tags and tv range, and decodes with the BT.709 matrix.
#include <gtest/gtest.h>

#include "cli/harness.h"

namespace sdfreel::test {
namespace {

TEST(H264, StreamCarriesBt709TagsAndTvRange) {
  if (!have_tool("ffprobe")) GTEST_SKIP() << "ffprobe not installed";
  const std::string dir = scratch_dir("h264-tags");
  write_file(dir + "/t.toml", small_timeline(3, "h264", "v.mp4"));
  ASSERT_EQ(run_sdfreel("render t.toml", dir).status, 0);
  const RunResult p = run("ffprobe -v error -show_streams out/v.mp4", dir);
  ASSERT_EQ(p.status, 0) << p.err;
  for (const char* want :
       {"codec_name=h264", "pix_fmt=yuv420p", "color_range=tv", "color_space=bt709",
        "color_transfer=bt709", "color_primaries=bt709", "nb_frames=3"})
    EXPECT_NE(p.out.find(want), std::string::npos) << want << "\n" << p.out;
}

}  // namespace
}  // namespace sdfreel::test
