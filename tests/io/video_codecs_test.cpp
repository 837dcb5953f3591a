// The lossy codecs beyond H.264 (HEVC, VP9, AV1) and the 10-bit ones: each in its container,
// read back with ffprobe (stream, pixel format, colour tags, frame count) and decoded with libav
// (the primaries come back through the BT.709 matrix).
#include <gtest/gtest.h>

#include <cmath>

extern "C" {
#include <libavutil/pixdesc.h>
}

#include "io/video_codecs.h"
#include "io/video_decode.h"
#include "io/video_test_support.h"
#include "timeline/video_codec_rules.h"

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

// A GIF decoded by stock ffmpeg: every frame, a solid colour exactly (in 8 bits), a frame of many
// colours within the palette's error.
TEST_F(VideoCodecsTest, GifHoldsEveryFrameInItsOwnPalette) {
  if (!have_program("ffmpeg")) GTEST_SKIP() << "ffmpeg not installed";
  // The middle frame: a smooth two-way ramp, as renders are (2304 colours on a surface).
  ImageRGB16 ramp(64, 36);
  for (int y = 0; y < 36; ++y)
    for (int x = 0; x < 64; ++x) {
      uint16_t* p = &ramp.pixels[(size_t(y) * 64 + x) * 3];
      p[0] = uint16_t(x * 65535 / 63);
      p[1] = uint16_t(y * 65535 / 35);
      p[2] = 20000;
    }
  std::vector<ImageRGB16> frames = {solid_frame(64, 36, 65535, 0, 0), ramp,
                                    solid_frame(64, 36, 0, 32896, 65535)};
  encode_video(file("loop.gif"), "gif", frames);
  int status = 0;
  const std::string raw = run_command("ffmpeg -v error -i " + file("loop.gif") +
                                          " -fps_mode passthrough -f rawvideo -pix_fmt rgb24 -",
                                      &status);
  ASSERT_EQ(status, 0);
  const size_t frame_bytes = 64 * 36 * 3;
  ASSERT_EQ(raw.size(), frames.size() * frame_bytes);
  for (size_t f = 0; f < frames.size(); ++f) {
    double sum = 0.0, worst = 0.0;
    for (size_t i = 0; i < frame_bytes; ++i) {
      const double want = (frames[f].pixels[i] * 255.0 + 32767) / 65535.0;
      const double e = std::fabs(uint8_t(raw[f * frame_bytes + i]) - std::floor(want));
      sum += e;
      worst = std::max(worst, e);
    }
    if (f != 1) {
      EXPECT_EQ(worst, 0.0) << "solid frame " << f;
    } else {
      // 2304 colours in 256 boxes of about 3x3 of the ramp's steps (4/255 and 7/255): about
      // 2.8/255 on average in red and green, none in blue.
      EXPECT_LT(sum / frame_bytes, 3.0) << "mean error of the ramp, 8-bit units";
    }
  }
}

// The timeline's codec table (names, pixel formats for messages) and libav's must not drift.
TEST_F(VideoCodecsTest, TheTimelinesTableAndTheEncodersAgree) {
  std::string names;
  for (const VideoCodecRule& rule : video_codec_rules()) {
    names += (names.empty() ? "" : ", ") + std::string(rule.name);
    const VideoCodecSpec* spec = find_video_codec(rule.name);
    ASSERT_NE(spec, nullptr) << rule.name;
    EXPECT_STREQ(av_get_pix_fmt_name(spec->pix_fmt), rule.pix_fmt) << rule.name;
    EXPECT_EQ(spec->even_size, rule.even_size) << rule.name;
  }
  EXPECT_EQ(known_video_codecs(), names);
}

TEST_F(VideoCodecsTest, AnEncoderTheMachineLacksIsNamed) {
  EXPECT_EQ(missing_video_encoder("vp9"), "");
  EXPECT_NE(missing_video_encoder("vp8").find("unknown codec 'vp8'"), std::string::npos);
}

}  // namespace
}  // namespace sdfreel::test
