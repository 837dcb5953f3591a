// Codec-independent behaviour: reproducible bytes, atomic output, clear errors.
#include <gtest/gtest.h>

extern "C" {
#include <libavcodec/version.h>
#include <libavformat/version.h>
}

#include <malloc.h>

#include <chrono>
#include <thread>

#include "io/video_decode.h"
#include "io/video_test_support.h"

namespace sdfreel::test {
namespace {

using VideoEncoderTest = VideoTest;

const char* const kCodecFiles[][2] = {{"h264", "v.mp4"},     {"ffv1", "v.mkv"},
                                      {"prores", "v.mov"},   {"h264-10bit", "h10.mp4"},
                                      {"hevc", "hevc.mp4"},  {"hevc-10bit", "hevc10.mkv"},
                                      {"vp9", "vp9.webm"},   {"av1", "av1.webm"},
                                      {"webp", "loop.webp"}, {"gif", "loop.gif"}};

std::vector<ImageRGB16> some_frames() {
  std::vector<ImageRGB16> frames;
  for (int i = 0; i < 10; ++i) frames.push_back(gradient_frame(64, 36, i));
  return frames;
}

// glibc fills every block it hands out with this byte while set (0: off). An encoder that reads
// memory it never wrote (x264's AVX-512 code did) then gives different bytes for each pattern.
void set_heap_fill(int byte) {
#ifdef __GLIBC__
  mallopt(M_PERTURB, byte);
#else
  (void)byte;
#endif
}

TEST_F(VideoEncoderTest, SameFramesGiveIdenticalBytes) {
  const auto frames = some_frames();
  const int fills[] = {0, 0xa5, 0x5a};
  for (int run = 0; run < 3; ++run) {
    std::filesystem::create_directories(dir_ / std::to_string(run));
    set_heap_fill(fills[run]);
    for (const auto& cf : kCodecFiles)
      encode_video(file(std::to_string(run) + "/" + cf[1]), cf[0], frames);
    set_heap_fill(0);
    // Past a second boundary, so a wall-clock time stamp in the file would show.
    if (run == 0) std::this_thread::sleep_for(std::chrono::milliseconds(1100));
  }
  for (const auto& cf : kCodecFiles) {
    const std::string first = read_bytes(file(std::string("0/") + cf[1]));
    EXPECT_GT(first.size(), 0u) << cf[0];
    for (int run = 1; run < 3; ++run)
      EXPECT_TRUE(read_bytes(file(std::to_string(run) + "/" + cf[1])) == first)
          << cf[0] << " encode " << run << " differs from the first";
    // Bit-exact mode: no libavformat/libavcodec version strings that change between builds.
    EXPECT_EQ(first.find(LIBAVFORMAT_IDENT), std::string::npos) << cf[0];
    EXPECT_EQ(first.find(LIBAVCODEC_IDENT), std::string::npos) << cf[0];
  }
}

TEST_F(VideoEncoderTest, DestroyedWithoutFinishLeavesNoFile) {
  for (const auto& cf : kCodecFiles) {
    VideoSettings s;
    s.path = file(cf[1]);
    s.codec = cf[0];
    s.width = 64;
    s.height = 36;
    {
      VideoEncoder enc(s);
      enc.add_frame(gradient_frame(64, 36, 0));
      enc.add_frame(gradient_frame(64, 36, 1));
      EXPECT_FALSE(list_dir(dir_).empty()) << "the encoder writes as it goes";
    }
    EXPECT_TRUE(list_dir(dir_).empty()) << cf[0];
  }
}

TEST_F(VideoEncoderTest, FinishLeavesOnlyTheFinalFile) {
  encode_video(file("out.mp4"), "h264", some_frames());
  EXPECT_EQ(list_dir(dir_), std::vector<std::string>{"out.mp4"});
}

TEST_F(VideoEncoderTest, FinishReplacesAnOlderFile) {
  { std::ofstream(file("out.mkv")) << "old"; }
  const auto frames = some_frames();
  encode_video(file("out.mkv"), "ffv1", frames);
  EXPECT_EQ(decode_video(file("out.mkv")).frames.size(), frames.size());
  EXPECT_EQ(list_dir(dir_), std::vector<std::string>{"out.mkv"});
}

TEST_F(VideoEncoderTest, KnownCodecs) {
  EXPECT_TRUE(is_known_codec("h264"));
  EXPECT_TRUE(is_known_codec("ffv1"));
  EXPECT_TRUE(is_known_codec("prores"));
  EXPECT_FALSE(is_known_codec("H264"));
  EXPECT_TRUE(is_known_codec("vp9"));
  EXPECT_FALSE(is_known_codec("vp8"));
  EXPECT_FALSE(is_known_codec(""));
}

// Each bad setting must fail in the constructor, name the problem and leave nothing behind.
TEST_F(VideoEncoderTest, BadSettingsAreRefusedClearly) {
  struct Case {
    const char* path;
    const char* codec;
    int w, h;
    Rational fps;
    const char* message_part;
  };
  const Case cases[] = {
      {"a.mp4", "vp8", 64, 36, {30, 1}, "unknown codec"},
      {"a.xyz", "h264", 64, 36, {30, 1}, "container"},
      {"a.mp4", "h264", 64, 35, {30, 1}, "even"},
      {"a.mkv", "ffv1", 0, 36, {30, 1}, "size"},
      {"a.mkv", "ffv1", 64, 36, {0, 1}, "frame rate"},
      {"missing/a.mkv", "ffv1", 64, 36, {30, 1}, "No such file"},
  };
  for (const Case& c : cases) {
    VideoSettings s;
    s.path = file(c.path);
    s.codec = c.codec;
    s.width = c.w;
    s.height = c.h;
    s.fps = c.fps;
    try {
      VideoEncoder enc(s);
      ADD_FAILURE() << c.path << " " << c.codec << " was accepted";
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find(c.message_part), std::string::npos) << e.what();
    }
    EXPECT_TRUE(list_dir(dir_).empty()) << c.path;
  }
}

TEST_F(VideoEncoderTest, WrongFrameSizeIsRefused) {
  VideoSettings s;
  s.path = file("v.mkv");
  s.codec = "ffv1";
  s.width = 64;
  s.height = 36;
  VideoEncoder enc(s);
  EXPECT_THROW(enc.add_frame(gradient_frame(32, 36, 0)), std::runtime_error);
  ImageRGB16 short_pixels(64, 36);
  short_pixels.pixels.resize(10);
  EXPECT_THROW(enc.add_frame(short_pixels), std::runtime_error);
}

}  // namespace
}  // namespace sdfreel::test
