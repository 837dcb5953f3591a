// `final`'s adaptive preset follows the frame's size (render/quality.h): small frames start every
// pixel at 4 samples and go to 28, the numbers a file gives still win, and the size is the one a
// command settles on (a --resolution override), not the file's. The frame context's and the
// bench's side: tests/pipeline/frame_context_adaptive_test.cpp, tests/bench/bench_presets_test.cpp.
#include <gtest/gtest.h>

#include "render/quality.h"
#include "timeline/fixture.h"

namespace sdfreel::testing {
namespace {

class AdaptiveAtSize : public TimelineFiles {
 protected:
  Timeline load(const std::string& video_keys) {
    return load_timeline(all_scenes(), write(video_with(video_keys)), nullptr);
  }
};

void expect_numbers(const AdaptiveSampling& a, int minimum, int maximum, float threshold) {
  EXPECT_TRUE(a.enabled);
  EXPECT_EQ(a.minimum, minimum);
  EXPECT_EQ(a.maximum, maximum);
  EXPECT_EQ(a.threshold, threshold);
}

TEST(SmallFrame, BelowThePixelsOf320x180) {
  EXPECT_TRUE(small_frame(160, 90));
  EXPECT_TRUE(small_frame(319, 180));
  EXPECT_FALSE(small_frame(320, 180));
  EXPECT_FALSE(small_frame(180, 320));
  EXPECT_FALSE(small_frame(1280, 720));
}

TEST_F(AdaptiveAtSize, FinalOnASmallFrameTakesFourToTwentyEight) {
  Timeline tl = load("resolution = [160, 90]\nadaptive = true");
  expect_numbers(tl.adaptive_at_size(), 4, 28, 0.008f);
  tl.width = 1280, tl.height = 720;  // as --resolution 1280x720 sets it
  const AdaptiveSampling full = adaptive_preset(Quality::Final);
  expect_numbers(tl.adaptive_at_size(), full.minimum, full.maximum, full.threshold);
  EXPECT_EQ(full.maximum, 16);
}

TEST_F(AdaptiveAtSize, OtherPresetsDoNotDependOnSize) {
  const Timeline tl = load("resolution = [160, 90]\nquality = \"draft\"\nadaptive = true");
  const AdaptiveSampling draft = adaptive_preset(Quality::Draft);
  expect_numbers(tl.adaptive_at_size(), draft.minimum, draft.maximum, draft.threshold);
}

TEST_F(AdaptiveAtSize, NumbersTheFileGivesWin) {
  expect_numbers(load("resolution = [160, 90]\nadaptive = { minimum = 1, maximum = 16, "
                      "threshold = 0.02 }")
                     .adaptive_at_size(),
                 1, 16, 0.02f);
  expect_numbers(load("resolution = [160, 90]\nadaptive = { threshold = 0.05 }").adaptive_at_size(),
                 4, 28, 0.05f);
  // A given bound below the small preset's other one pulls it along.
  expect_numbers(load("resolution = [160, 90]\nadaptive = { maximum = 3 }").adaptive_at_size(), 3,
                 3, 0.008f);
  expect_numbers(load("resolution = [160, 90]\nadaptive = { minimum = 12 }").adaptive_at_size(), 12,
                 28, 0.008f);
}

TEST_F(AdaptiveAtSize, FixedSamplingStaysFixed) {
  const Timeline tl = load("resolution = [160, 90]\nsamples = 16");
  EXPECT_FALSE(tl.adaptive_at_size().enabled);
}

}  // namespace
}  // namespace sdfreel::testing
