// H.264: yuv420p in tv range, tagged and converted with BT.709 (README.md, "Videos").
#include <gtest/gtest.h>

#include <algorithm>

#include "io/video_decode.h"
#include "io/video_test_support.h"

namespace sdfreel::test {
namespace {

using H264Test = VideoTest;

TEST_F(H264Test, StreamIsBt709TvRangeYuv420p) {
  if (!have_program("ffprobe")) GTEST_SKIP() << "ffprobe not installed";
  std::vector<ImageRGB16> frames;
  for (int i = 0; i < 10; ++i) frames.push_back(gradient_frame(64, 36, i));
  encode_video(file("v.mp4"), "h264", frames);
  auto s = probe_video_stream(file("v.mp4"));
  EXPECT_EQ(s["codec_name"], "h264");
  EXPECT_EQ(s["pix_fmt"], "yuv420p");
  EXPECT_EQ(s["width"], "64");
  EXPECT_EQ(s["height"], "36");
  EXPECT_EQ(s["color_primaries"], "bt709");
  EXPECT_EQ(s["color_transfer"], "bt709");
  EXPECT_EQ(s["color_space"], "bt709");
  EXPECT_EQ(s["color_range"], "tv");
  EXPECT_EQ(s["nb_read_frames"], "10");
  EXPECT_EQ(s["avg_frame_rate"], "30/1");
}

TEST_F(H264Test, FrameRateIsTheTimelineFraction) {
  if (!have_program("ffprobe")) GTEST_SKIP() << "ffprobe not installed";
  std::vector<ImageRGB16> frames(3, gradient_frame(64, 36, 0));
  encode_video(file("ntsc.mp4"), "h264", frames, Rational{30000, 1001});
  auto s = probe_video_stream(file("ntsc.mp4"));
  EXPECT_EQ(s["avg_frame_rate"], "30000/1001");
  EXPECT_EQ(s["nb_read_frames"], "3");
}

// Decoding with the BT.709 matrix must give the primaries back. The BT.601 matrix (swscale's
// default) would turn red into about (255, 23, 0).
TEST_F(H264Test, PrimariesSurviveTheBt709Matrix) {
  struct Colour {
    const char* name;
    uint16_t r, g, b;
  };
  const Colour colours[] = {{"red", 65535, 0, 0},
                            {"green", 0, 65535, 0},
                            {"blue", 0, 0, 65535},
                            {"white", 65535, 65535, 65535},
                            {"grey", 32768, 32768, 32768}};
  std::vector<ImageRGB16> frames;
  for (const Colour& c : colours)
    for (int repeat = 0; repeat < 2; ++repeat) frames.push_back(solid_frame(64, 36, c.r, c.g, c.b));
  encode_video(file("colours.mp4"), "h264", frames);

  const DecodedVideo video = decode_video(file("colours.mp4"));
  ASSERT_EQ(video.frames.size(), frames.size());
  for (size_t i = 0; i < frames.size(); ++i) {
    const Colour& c = colours[i / 2];
    const AVFrame& f = *video.frames[i];
    ASSERT_EQ(f.format, AV_PIX_FMT_YUV420P);
    const std::array<double, 3> rgb = bt709_pixel_to_rgb(f, 32, 18);
    const double want[3] = {c.r / 65535.0, c.g / 65535.0, c.b / 65535.0};
    for (int ch = 0; ch < 3; ++ch)
      EXPECT_NEAR(rgb[ch] * 255.0, want[ch] * 255.0, 6.0) << c.name << " channel " << ch;
    if (std::string(c.name) == "red") {
      EXPECT_LT(rgb[1] * 255.0, 8.0) << "BT.601 matrix used?";
    }
  }
}

// Top-level MP4 box types in file order.
std::vector<std::string> mp4_boxes(const std::string& bytes) {
  std::vector<std::string> types;
  size_t at = 0;
  while (at + 8 <= bytes.size()) {
    auto byte = [&](size_t i) { return uint64_t(uint8_t(bytes[i])); };
    uint64_t size = byte(at) << 24 | byte(at + 1) << 16 | byte(at + 2) << 8 | byte(at + 3);
    types.push_back(bytes.substr(at + 4, 4));
    if (size == 1 && at + 16 <= bytes.size()) {
      size = 0;
      for (int i = 0; i < 8; ++i) size = size << 8 | byte(at + 8 + i);
    }
    if (size < 8) break;
    at += size;
  }
  return types;
}

// +faststart: the index (moov) comes before the media data, so playback can start early.
TEST_F(H264Test, IndexComesFirst) {
  std::vector<ImageRGB16> frames(5, gradient_frame(64, 36, 2));
  encode_video(file("v.mp4"), "h264", frames);
  const std::vector<std::string> boxes = mp4_boxes(read_bytes(file("v.mp4")));
  const auto moov = std::find(boxes.begin(), boxes.end(), "moov");
  const auto mdat = std::find(boxes.begin(), boxes.end(), "mdat");
  ASSERT_NE(moov, boxes.end());
  ASSERT_NE(mdat, boxes.end());
  EXPECT_LT(moov - boxes.begin(), mdat - boxes.begin());
}

TEST_F(H264Test, OddSizeIsRefused) {
  VideoSettings s;
  s.path = file("odd.mp4");
  s.codec = "h264";
  s.width = 65;
  s.height = 36;
  try {
    VideoEncoder enc(s);
    FAIL() << "an odd width was accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("even"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(list_dir(dir_).empty());
}

}  // namespace
}  // namespace sdfreel::test
