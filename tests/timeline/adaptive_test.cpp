// [video] adaptive: presets, tables, target_db, the docs' example, and refusals at
// FILE:LINE:COLUMN.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "render/adaptive_target.h"
#include "render/quality.h"
#include "timeline/fixture.h"

namespace sdfreel::testing {
namespace {

class Adaptive : public TimelineFiles {
 protected:
  Timeline load(const std::string& text) {
    return load_timeline(all_scenes(), write(text), nullptr);
  }
};

TEST_F(Adaptive, AbsentMeansFixedSamples) {
  const Timeline tl = load(video_with("samples = 6"));
  EXPECT_FALSE(tl.adaptive.enabled);
  EXPECT_EQ(tl.samples, 6);
}

TEST_F(Adaptive, TrueTakesTheQualityPreset) {
  const Timeline tl = load(video_with("quality = \"draft\"\nadaptive = true"));
  const AdaptiveSampling want = adaptive_preset(Quality::Draft);
  EXPECT_TRUE(tl.adaptive.enabled);
  EXPECT_EQ(tl.adaptive.minimum, want.minimum);
  EXPECT_EQ(tl.adaptive.maximum, want.maximum);
  EXPECT_EQ(tl.adaptive.threshold, want.threshold);
  EXPECT_FALSE(load(video_with("adaptive = false")).adaptive.enabled);
}

TEST_F(Adaptive, TableSetsKeysAndThePresetFillsTheRest) {
  const Timeline tl = load(video_with("[video.adaptive]\nmaximum = 32\nthreshold = 0.002"));
  EXPECT_TRUE(tl.adaptive.enabled);
  EXPECT_EQ(tl.adaptive.minimum, adaptive_preset(Quality::Final).minimum);
  EXPECT_EQ(tl.adaptive.maximum, 32);
  EXPECT_EQ(tl.adaptive.threshold, 0.002f);
  const Timeline db = load(video_with("adaptive = { target_db = 40 }"));
  EXPECT_EQ(db.adaptive.threshold, threshold_for_target_db(40.0));
  EXPECT_GT(db.adaptive.threshold, 0.07f);  // 40 dB is below the lanterns' 41.5 at 0.07
}

TEST_F(Adaptive, TheDocsExampleParses) {
  std::ifstream in(std::string(SDFREEL_SOURCE_DIR) + "/docs/timeline.md");
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string doc = ss.str();
  const size_t at = doc.find("adaptive = {");
  ASSERT_NE(at, std::string::npos);
  const size_t start = doc.rfind("```toml\n", at) + 8, end = doc.find("```", at);
  const Timeline tl = load(doc.substr(start, end - start));
  EXPECT_TRUE(tl.adaptive.enabled);
  EXPECT_EQ(tl.adaptive.maximum, 16);
}

TEST_F(Adaptive, BadValuesAreRefusedWhereTheyStand) {
  expect_error(video_with("samples = 4\nadaptive = true"), "exclude each other", 3, 11);
  expect_error(video_with("adaptive = 3"), "video.adaptive must be true, false or a table", 3, 12);
  expect_error(video_with("adaptive = { minimum = 0 }"), "video.adaptive.minimum", 3, 24);
  expect_error(video_with("adaptive = { maximum = 2000 }"), "video.adaptive.maximum", 3, 24);
  expect_error(video_with("adaptive = { minimum = 8, maximum = 4 }"),
               "must be at least video.adaptive.minimum", 3, 37);
  expect_error(video_with("adaptive = { threshold = -0.1 }"), "threshold must be in 0..1", 3, 26);
  expect_error(video_with("adaptive = { target_db = 0.5 }"), "target_db must be in 1..120", 3, 26);
  expect_error(video_with("adaptive = { threshold = 0.1, target_db = 40 }"), "not both", 3, 43);
  expect_error(video_with("adaptive = { treshold = 0.1 }"), "did you mean 'threshold'", 3, 14);
}

}  // namespace
}  // namespace sdfreel::testing
