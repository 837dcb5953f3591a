// Timeline's frame arithmetic, InputError formatting and checks after command-line overrides.
#include "timeline/timeline.h"

#include <gtest/gtest.h>

namespace sdfreel {
namespace {

TEST(Timeline, FrameCountRoundsDurationTimesFps) {
  Timeline tl;
  tl.fps = {30, 1};
  tl.duration = 12.0;
  EXPECT_EQ(tl.frame_count(), 360);
  tl.fps = {30000, 1001};
  tl.duration = 10.0;
  EXPECT_EQ(tl.frame_count(), 300);  // 299.7
  tl.duration = 0.001;
  EXPECT_EQ(tl.frame_count(), 1);  // at least one frame
}

TEST(Timeline, VideoTimeIsExactForRationalFps) {
  Timeline tl;
  tl.fps = {30000, 1001};
  EXPECT_EQ(tl.video_time(0), 0.0);
  EXPECT_EQ(tl.video_time(30000), 1001.0);
  EXPECT_EQ(tl.video_time(7), 7007.0 / 30000.0);
  tl.fps = {24, 1};
  EXPECT_EQ(tl.video_time(36), 1.5);
}

TEST(Timeline, SceneTimeFollowsTheTimeCurve) {
  Timeline tl;
  tl.fps = {10, 1};
  EXPECT_EQ(tl.scene_time(25), 2.5);  // no curve: TIME = t
  Curve reverse;
  reverse.t = {0, 10};
  reverse.values = {{100}, {0}};
  tl.time = reverse;
  EXPECT_DOUBLE_EQ(tl.scene_time(25), 75.0);
}

TEST(InputError, FormatsFileLineColumn) {
  EXPECT_EQ(InputError("a.toml", 3, 7, "bad").formatted(), "a.toml:3:7: error: bad");
  EXPECT_EQ(InputError("a.toml", 3, 0, "bad").formatted(), "a.toml:3: error: bad");
  EXPECT_EQ(InputError("a.toml", 0, 0, "bad").formatted(), "a.toml: error: bad");
  EXPECT_STREQ(InputError("a.toml", 1, 1, "bad").what(), "bad");
}

Timeline overridden(int w, int h, int samples, const std::string& video) {
  Timeline tl;
  tl.path = "show.toml";
  tl.width = w;
  tl.height = h;
  tl.samples = samples;
  tl.video = video;
  return tl;
}

void expect_override_error(const Timeline& tl, const std::string& message) {
  try {
    validate_overrides(tl, true);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file, "show.toml");
    EXPECT_EQ(e.line, 0);
    EXPECT_EQ(e.column, 0);
    EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
  }
}

TEST(ValidateOverrides, ChecksResolutionSamplesAndEvenSizes) {
  EXPECT_NO_THROW(validate_overrides(overridden(64, 36, 4, "a.mp4"), true));
  expect_override_error(overridden(0, 36, 4, ""), "resolution 0x36 is outside 1..16384");
  expect_override_error(overridden(64, 20000, 4, ""), "is outside 1..16384");
  expect_override_error(overridden(64, 36, 0, ""), "samples 0 is outside 1..1024");
  expect_override_error(overridden(64, 36, 2000, ""), "samples 2000 is outside 1..1024");
  expect_override_error(overridden(63, 35, 4, "a.mp4"), "use 64x36");
  // No video (--no-video, a still, a partial range): odd sizes are fine; so are other codecs.
  EXPECT_NO_THROW(validate_overrides(overridden(63, 35, 4, ""), true));
  EXPECT_NO_THROW(validate_overrides(overridden(63, 35, 4, "a.mp4"), false));
  Timeline ffv1 = overridden(63, 35, 4, "a.mkv");
  ffv1.codec = "ffv1";
  EXPECT_NO_THROW(validate_overrides(ffv1, true));
}

// The size rule points at [video] resolution when the size is the file's.
TEST(ValidateOverrides, TheSizeRuleNamesTheResolutionsPlace) {
  Timeline tl = overridden(63, 35, 4, "a.mp4");
  tl.resolution_line = 6;
  tl.resolution_column = 14;
  try {
    validate_overrides(tl, true);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.line, 6);
    EXPECT_EQ(e.column, 14);
  }
}

}  // namespace
}  // namespace sdfreel
