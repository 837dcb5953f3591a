// The timeline's table of which container holds which codec (timeline/output_rules.cpp) agrees
// with what libav's muxers accept, so a timeline that passes validation never fails at encode.
#include <gtest/gtest.h>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
}

#include "io/video_codecs.h"
#include "timeline/rules.h"

namespace sdfreel {
namespace {

// Our pairings are our own rule, the same on every FFmpeg: each must be one the installed libav can
// mux, but a newer libav may accept more (FFmpeg 8 puts ffv1 in MP4) without changing the rule.
TEST(ContainerRules, AreOnesLibavCanMux) {
  for (const char* name : {"v.mp4", "v.mkv", "v.mov"}) {
    const AVOutputFormat* container = av_guess_format(nullptr, name, nullptr);
    ASSERT_NE(container, nullptr) << name;
    for (const char* codec : {"h264", "ffv1", "prores"}) {
      const VideoCodecSpec* spec = find_video_codec(codec);
      ASSERT_NE(spec, nullptr);
      const AVCodec* encoder = avcodec_find_encoder_by_name(spec->encoder);
      if (!encoder) continue;  // not in this libav: nothing to compare
      const bool libav = avformat_query_codec(container, encoder->id, FF_COMPLIANCE_NORMAL) == 1;
      if (check_video_name(name, codec).empty()) {
        EXPECT_TRUE(libav) << name << " " << codec;
      }
    }
  }
  // The documented pairings (docs/timeline.md) and the refusals that do not depend on libav.
  EXPECT_EQ(check_video_name("v.mp4", "h264"), "");
  EXPECT_EQ(check_video_name("v.mkv", "ffv1"), "");
  EXPECT_EQ(check_video_name("v.mov", "prores"), "");
  EXPECT_NE(check_video_name("v.mp4", "ffv1"), "");
  EXPECT_NE(check_video_name("v.avi", "h264"), "");
  EXPECT_NE(check_video_name("dir/v.mkv", "ffv1"), "");
  EXPECT_EQ(check_video_name("V.MKV", "ffv1"), "");
  EXPECT_EQ(check_video_name("", "ffv1"), "");
}

}  // namespace
}  // namespace sdfreel
