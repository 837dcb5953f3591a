// ProRes 4444 in a .mov: decodes at the right size and count, profile 4444, BT.709 colours.
#include <gtest/gtest.h>

#include "io/video_decode.h"
#include "io/video_test_support.h"

namespace sdfreel::test {
namespace {

using ProresTest = VideoTest;

TEST_F(ProresTest, DecodesAtTheRightSizeAndCount) {
  std::vector<ImageRGB16> frames;
  for (int i = 0; i < 10; ++i) frames.push_back(gradient_frame(64, 36, i));
  encode_video(file("v.mov"), "prores", frames);
  const DecodedVideo video = decode_video(file("v.mov"));
  EXPECT_EQ(video.codec, "prores");
  ASSERT_EQ(video.frames.size(), 10u);
  for (const AvFramePtr& f : video.frames) {
    EXPECT_EQ(f->width, 64);
    EXPECT_EQ(f->height, 36);
    // FFmpeg's ProRes decoder returns 4444 as 12-bit.
    EXPECT_TRUE(f->format == AV_PIX_FMT_YUV444P10LE || f->format == AV_PIX_FMT_YUV444P12LE);
  }
}

TEST_F(ProresTest, StreamIsProfile4444Bt709) {
  if (!have_program("ffprobe")) GTEST_SKIP() << "ffprobe not installed";
  std::vector<ImageRGB16> frames(10, gradient_frame(64, 36, 1));
  encode_video(file("v.mov"), "prores", frames);
  auto s = probe_video_stream(file("v.mov"));
  EXPECT_EQ(s["codec_name"], "prores");
  EXPECT_EQ(s["profile"], "4444");
  EXPECT_EQ(s["pix_fmt"].rfind("yuv444p1", 0), 0u) << s["pix_fmt"];  // 10 or 12 bit, 4:4:4
  EXPECT_EQ(s["color_primaries"], "bt709");
  EXPECT_EQ(s["color_transfer"], "bt709");
  EXPECT_EQ(s["color_space"], "bt709");
  EXPECT_EQ(s["nb_read_frames"], "10");
}

TEST_F(ProresTest, RedDecodesWithTheBt709Matrix) {
  std::vector<ImageRGB16> frames(2, solid_frame(64, 36, 65535, 0, 0));
  encode_video(file("red.mov"), "prores", frames);
  const DecodedVideo video = decode_video(file("red.mov"));
  ASSERT_EQ(video.frames.size(), 2u);
  const std::array<double, 3> rgb = bt709_pixel_to_rgb(*video.frames[0], 32, 18);
  EXPECT_NEAR(rgb[0] * 255.0, 255.0, 2.0);
  EXPECT_NEAR(rgb[1] * 255.0, 0.0, 2.0);
  EXPECT_NEAR(rgb[2] * 255.0, 0.0, 2.0);
}

}  // namespace
}  // namespace sdfreel::test
