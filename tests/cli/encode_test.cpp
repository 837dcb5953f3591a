// `sdfreel encode`: without --codec the container names it; an ambiguous name is refused.
#include <gtest/gtest.h>

#include <filesystem>

#include "cli/harness.h"

namespace sdfreel::test {
namespace {

namespace fs = std::filesystem;

// A scratch folder holding out/, a render of `frames` frames in `codec` without its video.
std::string rendered(const std::string& name, int frames, const std::string& codec,
                     const std::string& video) {
  const std::string dir = scratch_dir(name);
  write_file(dir + "/t.toml", small_timeline(frames, codec, video));
  EXPECT_EQ(run_sdfreel("render t.toml --no-video", dir).status, 0);
  return dir;
}

// Encodes out/ into `name` (more options in `args`): exit 0, and the codec it used.
void expect_encoded(const std::string& dir, const std::string& name, const std::string& args,
                    const std::string& said) {
  const RunResult r = run_sdfreel("encode out -o " + name + args, dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find(said), std::string::npos) << r.err;
}

TEST(Encode, TheContainerNamesTheCodecAndAnAmbiguousOneIsRefused) {
  const std::string dir = rendered("encode-codec", 3, "h264", "v.mp4");
  expect_encoded(dir, "a.mp4", "", "(3 frames, h264)");
  // h264 fits a .mkv and a .mov, whose own codecs are ffv1 and prores: which one is meant?
  for (const char* name : {"b.mkv", "c.mov"}) {
    const RunResult r = run_sdfreel(std::string("encode out -o ") + name, dir);
    EXPECT_EQ(r.status, 2) << name;
    EXPECT_NE(r.err.find("say which with --codec"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir + "/" + name));
  }
  expect_encoded(dir, "b.mkv", " --codec ffv1", "(3 frames, ffv1)");
}

TEST(Encode, ARenderInACodecTheContainerCannotHoldTakesTheContainers) {
  const std::string dir = rendered("encode-container", 2, "ffv1", "v.mkv");
  expect_encoded(dir, "same.mkv", "", "(2 frames, ffv1)");
  expect_encoded(dir, "other.mp4", "", "(2 frames, h264)");  // ffv1 cannot go in a .mp4
}

// WebM: its usual codec is vp9; a render in av1, which a .webm also holds, is asked which.
TEST(Encode, AWebmTakesVp9AndAsksARenderInAv1) {
  const std::string dir = scratch_dir("encode-webm");
  write_file(dir + "/t.toml", small_timeline(3, "av1", "v.webm"));
  const RunResult r = run_sdfreel("render t.toml", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string video = read_file(dir + "/out/v.webm");
  ASSERT_GT(video.size(), 4u);
  EXPECT_EQ(video.substr(0, 4), "\x1a\x45\xdf\xa3");  // EBML: Matroska and WebM
  const RunResult asked = run_sdfreel("encode out -o a.webm", dir);
  EXPECT_EQ(asked.status, 2);
  EXPECT_NE(asked.err.find("say which with --codec vp9 or --codec av1"), std::string::npos)
      << asked.err;
  EXPECT_FALSE(fs::exists(dir + "/a.webm"));
  expect_encoded(dir, "a.webm", " --codec vp9", "(3 frames, vp9)");
  expect_encoded(dir, "loop.webp", "", "(3 frames, webp)");  // the container's only codec
  const RunResult wrong = run_sdfreel("encode out -o b.webm --codec h264", dir);
  EXPECT_EQ(wrong.status, 2);
  EXPECT_NE(wrong.err.find("cannot hold codec h264"), std::string::npos) << wrong.err;
}

}  // namespace
}  // namespace sdfreel::test
