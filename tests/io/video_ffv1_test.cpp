// FFV1 is the lossless codec: what goes in must come out bit for bit, and FFmpeg's framemd5 of
// the file must equal the MD5 of the packed rgb48le input (the frames.framemd5 contract).
#include <gtest/gtest.h>

extern "C" {
#include <libavutil/md5.h>
}

#include <cstdio>

#include "io/video_decode.h"
#include "io/video_test_support.h"

namespace sdfreel::test {
namespace {

std::vector<ImageRGB16> gradient_frames(int w, int h, int count) {
  std::vector<ImageRGB16> frames;
  for (int i = 0; i < count; ++i) frames.push_back(gradient_frame(w, h, i));
  return frames;
}

std::string md5_hex_rgb48le(const ImageRGB16& img) {
  std::vector<uint8_t> bytes;
  for (uint16_t v : img.pixels) {
    bytes.push_back(uint8_t(v & 0xff));
    bytes.push_back(uint8_t(v >> 8));
  }
  uint8_t digest[16];
  av_md5_sum(digest, bytes.data(), bytes.size());
  char hex[33];
  for (int i = 0; i < 16; ++i) std::snprintf(hex + 2 * i, 3, "%02x", digest[i]);
  return hex;
}

void expect_lossless(const std::string& path, const std::vector<ImageRGB16>& frames) {
  const DecodedVideo video = decode_video(path);
  EXPECT_EQ(video.codec, "ffv1");
  ASSERT_EQ(video.frames.size(), frames.size());
  for (size_t i = 0; i < frames.size(); ++i) {
    const AVFrame& f = *video.frames[i];
    ASSERT_EQ(f.width, frames[i].width);
    ASSERT_EQ(f.height, frames[i].height);
    EXPECT_EQ(gbrp16_to_rgb48(f), frames[i].pixels) << "frame " << i;
  }
}

using Ffv1Test = VideoTest;

TEST_F(Ffv1Test, RoundTripIsLossless) {
  const auto frames = gradient_frames(64, 36, 10);
  encode_video(file("v.mkv"), "ffv1", frames);
  expect_lossless(file("v.mkv"), frames);
}

TEST_F(Ffv1Test, OddSizeRoundTripIsLossless) {
  const auto frames = gradient_frames(33, 17, 3);
  encode_video(file("odd.mkv"), "ffv1", frames);
  expect_lossless(file("odd.mkv"), frames);
}

TEST_F(Ffv1Test, FfmpegFramemd5EqualsInputMd5) {
  if (!have_program("ffmpeg")) GTEST_SKIP() << "ffmpeg not installed";
  const auto frames = gradient_frames(64, 36, 10);
  encode_video(file("v.mkv"), "ffv1", frames);
  const std::vector<std::string> hashes = framemd5_rgb48le(file("v.mkv"));
  ASSERT_EQ(hashes.size(), frames.size());
  for (size_t i = 0; i < frames.size(); ++i)
    EXPECT_EQ(hashes[i], md5_hex_rgb48le(frames[i])) << "frame " << i;
}

TEST_F(Ffv1Test, StreamIsVersion3Gbrp16) {
  if (!have_program("ffprobe")) GTEST_SKIP() << "ffprobe not installed";
  encode_video(file("v.mkv"), "ffv1", gradient_frames(64, 36, 4), Rational{30000, 1001});
  auto s = probe_video_stream(file("v.mkv"));
  EXPECT_EQ(s["codec_name"], "ffv1");
  EXPECT_EQ(s["pix_fmt"], "gbrp16le");
  EXPECT_EQ(s["nb_read_frames"], "4");
  EXPECT_EQ(s["avg_frame_rate"], "30000/1001");
  // ffprobe has no level for FFV1; the decoder's debug output names the bitstream version.
  int status = 0;
  const std::string debug = run_command(
      "ffprobe -v debug -debug pict -show_frames '" + file("v.mkv") + "' 2>&1", &status);
  EXPECT_EQ(status, 0);
  EXPECT_NE(debug.find("global: ver:3."), std::string::npos) << "not FFV1 version 3";
}

}  // namespace
}  // namespace sdfreel::test
