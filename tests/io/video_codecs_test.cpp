// The lossy codecs beyond H.264 (HEVC, VP9, AV1) and the 10-bit ones: each in its container,
// read back with ffprobe (stream, pixel format, colour tags, frame count) and decoded with libav
// (the primaries come back through the BT.709 matrix).
#include "io/video_codecs.h"

#include <gtest/gtest.h>

#include "io/video_decode.h"
#include "io/video_test_support.h"

namespace sdfreel::test {
namespace {

using VideoCodecsTest = VideoTest;

struct Case {
  const char* codec;
  const char* file;
  const char* codec_name;  // ffprobe's
  const char* pix_fmt;
  AVPixelFormat decoded;
};

const Case kCases[] = {
    {"h264-10bit", "a.mp4", "h264", "yuv420p10le", AV_PIX_FMT_YUV420P10LE},
    {"hevc", "b.mp4", "hevc", "yuv420p", AV_PIX_FMT_YUV420P},
    {"hevc-10bit", "c.mov", "hevc", "yuv420p10le", AV_PIX_FMT_YUV420P10LE},
    {"vp9", "d.webm", "vp9", "yuv420p", AV_PIX_FMT_YUV420P},
    {"av1", "e.webm", "av1", "yuv420p", AV_PIX_FMT_YUV420P},
    {"av1", "f.mp4", "av1", "yuv420p", AV_PIX_FMT_YUV420P},
};

TEST_F(VideoCodecsTest, EachStreamIsTaggedBt709TvRangeWithEveryFrame) {
  if (!have_program("ffprobe")) GTEST_SKIP() << "ffprobe not installed";
  std::vector<ImageRGB16> frames;
  for (int i = 0; i < 8; ++i) frames.push_back(gradient_frame(64, 36, i));
  for (const Case& c : kCases) {
    if (!missing_video_encoder(c.codec).empty()) {
      ADD_FAILURE() << missing_video_encoder(c.codec);  // Debian's libav has them all
      continue;
    }
    encode_video(file(c.file), c.codec, frames, Rational{24, 1});
    auto s = probe_video_stream(file(c.file));
    EXPECT_EQ(s["codec_name"], c.codec_name) << c.codec;
    EXPECT_EQ(s["pix_fmt"], c.pix_fmt) << c.codec;
    EXPECT_EQ(s["width"], "64") << c.codec;
    EXPECT_EQ(s["color_primaries"], "bt709") << c.codec;
    EXPECT_EQ(s["color_transfer"], "bt709") << c.codec;
    EXPECT_EQ(s["color_space"], "bt709") << c.codec;
    EXPECT_EQ(s["color_range"], "tv") << c.codec;
    EXPECT_EQ(s["nb_read_frames"], "8") << c.codec;
    EXPECT_EQ(s["avg_frame_rate"], "24/1") << c.codec;
    if (std::string(c.codec_name) == "hevc" && std::string(c.file).find(".m") == 1) {
      EXPECT_EQ(s["codec_tag_string"], "hvc1") << c.file;
    }
  }
}

TEST_F(VideoCodecsTest, PrimariesSurviveTheBt709Matrix) {
  const uint16_t colours[][3] = {
      {65535, 0, 0}, {0, 65535, 0}, {0, 0, 65535}, {32768, 32768, 32768}};
  std::vector<ImageRGB16> frames;
  for (const auto& c : colours)
    for (int repeat = 0; repeat < 2; ++repeat)
      frames.push_back(solid_frame(64, 36, c[0], c[1], c[2]));
  for (const Case& c : kCases) {
    encode_video(file(c.file), c.codec, frames);
    const DecodedVideo video = decode_video(file(c.file));
    ASSERT_EQ(video.frames.size(), frames.size()) << c.codec;
    for (size_t i = 0; i < frames.size(); ++i) {
      const AVFrame& f = *video.frames[i];
      ASSERT_EQ(f.format, c.decoded) << c.codec;
      const std::array<double, 3> rgb = bt709_pixel_to_rgb(f, 32, 18);
      for (int ch = 0; ch < 3; ++ch)
        EXPECT_NEAR(rgb[ch] * 255.0, colours[i / 2][ch] / 257.0, 6.0)
            << c.codec << " frame " << i << " channel " << ch;
    }
  }
}

// Stock FFmpeg 5 cannot decode an animated WebP, so its chunks are read here: the RIFF header,
// ANIM with a loop count of 0 (forever) and one ANMF chunk a frame.
TEST_F(VideoCodecsTest, AnimatedWebpLoopsForeverWithEveryFrame) {
  std::vector<ImageRGB16> frames;
  for (int i = 0; i < 5; ++i) frames.push_back(gradient_frame(64, 36, i));
  encode_video(file("loop.webp"), "webp", frames);
  const std::string bytes = read_bytes(file("loop.webp"));
  ASSERT_GT(bytes.size(), 30u);
  EXPECT_EQ(bytes.substr(0, 4), "RIFF");
  EXPECT_EQ(bytes.substr(8, 4), "WEBP");
  const size_t anim = bytes.find("ANIM");
  ASSERT_NE(anim, std::string::npos);
  EXPECT_EQ(uint8_t(bytes[anim + 12]) | uint8_t(bytes[anim + 13]) << 8, 0) << "loop count";
  size_t frames_found = 0;
  for (size_t at = 0; (at = bytes.find("ANMF", at)) != std::string::npos; at += 4) ++frames_found;
  EXPECT_EQ(frames_found, 5u);
}

TEST_F(VideoCodecsTest, AnEncoderTheMachineLacksIsNamed) {
  EXPECT_EQ(missing_video_encoder("vp9"), "");
  EXPECT_NE(missing_video_encoder("vp8").find("unknown codec 'vp8'"), std::string::npos);
}

}  // namespace
}  // namespace sdfreel::test
