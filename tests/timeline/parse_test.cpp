// load_timeline on good files: the spec's example (with a scene that exists), defaults, forms.
#include <gtest/gtest.h>

#include "scenes/registry.h"
#include "timeline/fixture.h"
#include "timeline/sha256.h"

namespace sdfreel {
namespace {

using testing::TimelineFiles;
using testing::video_with;

// the timeline contract's example (docs/timeline.md), with the sdf_morph scene and its parameters.
const char* kSpecExample = R"([video]
scene      = "sdf_morph"
fps        = 30                   # integer, or a rational string such as "30000/1001"
duration   = 12.0
resolution = [1280, 720]
samples    = 4
quality    = "final"
seed       = 1

[output]
dir    = "output/sdf_morph"
frames = ["exr", "png"]
video  = "sdf_morph.mp4"
codec  = "h264"
crf    = 18

[color]
config = "builtin"
display = "sRGB"
view    = "ACES 1.0 - SDR Video"

[time]
interpolation = "linear"
keys = [[0.0, 0.0], [12.0, 12.0]]

[camera]
interpolation = "catmull-rom"
speed = "keys"
keys = [
  { t = 0.0,  position = [0.0, 2.0, -12.0], target = [0.0, 0.5, 0.0], fov = 50.0 },
  { t = 12.0, position = [6.0, 1.2, -2.0],  target = [0.0, 0.8, 4.0], fov = 40.0, roll = 0.0 },
]

[params]
reflectivity = 0.15
color = [0.2, 0.4, 0.6]
[params.morph_period]
interpolation = "smooth"
keys = [[0.0, 6.0], [6.0, 10.0]]
)";

struct RecordingChecker : ColorChecker {
  mutable std::string config, display, view;
  std::string check(const std::string& c, const std::string& d,
                    const std::string& v) const override {
    config = c, display = d, view = v;
    return "";
  }
};

class Parse : public TimelineFiles {};

TEST_F(Parse, SpecExample) {
  RecordingChecker color;
  const std::string path = write(kSpecExample);
  Timeline tl = load_timeline(all_scenes(), path, &color);
  EXPECT_EQ(tl.path, path);
  EXPECT_EQ(tl.sha256, sha256_hex(kSpecExample));
  EXPECT_EQ(tl.scene, "sdf_morph");
  EXPECT_EQ(tl.fps.num, 30);
  EXPECT_EQ(tl.fps.den, 1);
  EXPECT_EQ(tl.duration, 12.0);
  EXPECT_EQ(tl.frame_count(), 360);
  EXPECT_EQ(tl.width, 1280);
  EXPECT_EQ(tl.height, 720);
  EXPECT_EQ(tl.samples, 4);
  EXPECT_EQ(tl.quality, Quality::Final);
  EXPECT_EQ(tl.seed, 1u);

  EXPECT_EQ(tl.out_dir, "output/sdf_morph");
  EXPECT_TRUE(tl.write_exr);
  EXPECT_TRUE(tl.write_png);
  EXPECT_EQ(tl.video, "sdf_morph.mp4");
  EXPECT_EQ(tl.codec, "h264");
  EXPECT_EQ(tl.crf, 18);

  EXPECT_EQ(tl.color_config, "builtin");
  EXPECT_EQ(color.config, "builtin");
  EXPECT_EQ(color.display, "sRGB");
  EXPECT_EQ(color.view, "ACES 1.0 - SDR Video");

  ASSERT_TRUE(tl.time);
  EXPECT_EQ(tl.time->interp, Interp::Linear);
  EXPECT_EQ(tl.time->t, (std::vector<double>{0.0, 12.0}));
  EXPECT_DOUBLE_EQ(tl.scene_time(90), 3.0);

  EXPECT_EQ(tl.camera.interp, Interp::CatmullRom);
  EXPECT_FALSE(tl.camera.constant_speed);
  ASSERT_EQ(tl.camera.keys.size(), 2u);
  EXPECT_EQ(tl.camera.keys[0].pose.position, glm::dvec3(0.0, 2.0, -12.0));
  EXPECT_EQ(tl.camera.keys[0].pose.target, glm::dvec3(0.0, 0.5, 0.0));
  EXPECT_EQ(tl.camera.keys[0].pose.fov_deg, 50.0);
  EXPECT_EQ(tl.camera.keys[0].pose.roll_deg, 0.0);
  EXPECT_EQ(tl.camera.keys[1].t, 12.0);
  EXPECT_EQ(tl.camera.keys[1].pose.target, glm::dvec3(0.0, 0.8, 4.0));
  EXPECT_EQ(tl.camera.keys[1].pose.fov_deg, 40.0);

  // Parameters in file order: two constants, then the animated one.
  ASSERT_EQ(tl.params.size(), 3u);
  EXPECT_EQ(tl.params[0].name, "reflectivity");
  EXPECT_EQ(tl.params[0].curve.sample(5.0), std::vector<double>{0.15});
  EXPECT_EQ(tl.params[1].name, "color");
  EXPECT_EQ(tl.params[1].curve.sample(0.0), (std::vector<double>{0.2, 0.4, 0.6}));
  EXPECT_EQ(tl.params[2].name, "morph_period");
  EXPECT_EQ(tl.params[2].curve.interp, Interp::Smooth);
  EXPECT_DOUBLE_EQ(tl.params[2].curve.sample(3.0)[0], 8.0);
  EXPECT_EQ(tl.params[2].curve.sample(9.0)[0], 10.0);
}

TEST_F(Parse, MinimalFileTakesDefaults) {
  Timeline tl = load_timeline(all_scenes(),
                              write("[video]\nscene = \"sdf_morph\"\n", "my_show.toml"), nullptr);
  EXPECT_EQ(tl.out_dir, "output/my_show");
  EXPECT_FALSE(tl.time);  // TIME = t
  EXPECT_EQ(tl.scene_time(45), tl.video_time(45));
  EXPECT_TRUE(tl.camera.keys.empty());
  EXPECT_TRUE(tl.params.empty());
  EXPECT_EQ(tl.video, "");
  Timeline defaults;
  EXPECT_EQ(tl.width, defaults.width);
  EXPECT_EQ(tl.samples, defaults.samples);
  EXPECT_EQ(tl.codec, defaults.codec);
}

TEST_F(Parse, RationalFpsAndRelativeDir) {
  Timeline tl = load_timeline(all_scenes(), write(R"([video]
scene = "sdf_morph"
fps = "30000/1001"
duration = 10
[output]
dir = "renders/take2"
frames = ["png"]
codec = "ffv1"
)"),
                              nullptr);
  EXPECT_EQ(tl.fps.num, 30000);
  EXPECT_EQ(tl.fps.den, 1001);
  EXPECT_EQ(tl.frame_count(), 300);  // round(299.7)
  EXPECT_EQ(tl.out_dir, "renders/take2");
  EXPECT_FALSE(tl.write_exr);
  EXPECT_TRUE(tl.write_png);
  EXPECT_EQ(tl.codec, "ffv1");
}

TEST_F(Parse, RationalFpsIsReduced) {
  Timeline tl = load_timeline(all_scenes(), write(video_with("fps = \"60/2\"")), nullptr);
  EXPECT_EQ(tl.fps.num, 30);
  EXPECT_EQ(tl.fps.den, 1);
  tl = load_timeline(all_scenes(), write(video_with("fps = \"24\"")), nullptr);
  EXPECT_EQ(tl.fps.num, 24);
  EXPECT_EQ(tl.fps.den, 1);
}

TEST_F(Parse, CameraKeysTakeSceneFovAndZeroRollByDefault) {
  Timeline tl = load_timeline(all_scenes(), write(R"([video]
scene = "sdf_morph"
[camera]
speed = "constant"
interpolation = "linear"
[[camera.keys]]
t = 0
position = [0, 1, -4]
target = [0, 0, 0]
[[camera.keys]]
t = 2
position = [1, 1, -4]
target = [0, 0, 0]
roll = 15
)"),
                              nullptr);
  ASSERT_EQ(tl.camera.keys.size(), 2u);
  EXPECT_TRUE(tl.camera.constant_speed);
  EXPECT_EQ(tl.camera.interp, Interp::Linear);
  EXPECT_EQ(tl.camera.keys[0].pose.fov_deg, 40.0);  // sdf_morph's default camera
  EXPECT_EQ(tl.camera.keys[0].pose.roll_deg, 0.0);
  EXPECT_EQ(tl.camera.keys[1].pose.roll_deg, 15.0);
}

// A key that leaves out fov or roll holds the previous key's, as animation tools do: 55, (left
// out), 40 zooms from 55 to 40 without passing through the scene's default (40 for sdf_morph).
TEST_F(Parse, CameraKeysHoldThePreviousFovAndRoll) {
  Timeline tl = load_timeline(all_scenes(), write(R"([video]
scene = "sdf_morph"
[camera]
keys = [
  { t = 0, position = [0, 1, -4], target = [0, 0, 0], fov = 55, roll = 10 },
  { t = 1, position = [1, 1, -4], target = [0, 0, 0] },
  { t = 2, position = [2, 1, -4], target = [0, 0, 0], fov = 40 },
  { t = 3, position = [3, 1, -4], target = [0, 0, 0], roll = -5 },
]
)"),
                              nullptr);
  ASSERT_EQ(tl.camera.keys.size(), 4u);
  const double fov[] = {55, 55, 40, 40}, roll[] = {10, 10, 10, -5};
  for (size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(tl.camera.keys[i].pose.fov_deg, fov[i]) << "key " << i;
    EXPECT_EQ(tl.camera.keys[i].pose.roll_deg, roll[i]) << "key " << i;
  }
  EXPECT_NEAR(tl.camera.sample(0.5, CameraPose{}).fov_deg, 55.0, 1e-9);  // held, not pulled to 40
}

TEST_F(Parse, TimeMayRunBackwardsAndHold) {
  Timeline tl = load_timeline(all_scenes(), write(R"([video]
scene = "sdf_morph"
fps = 10
[time]
keys = [[0, 5], [1, 5], [2, 3]]
)"),
                              nullptr);
  EXPECT_DOUBLE_EQ(tl.scene_time(5), 5.0);
  EXPECT_DOUBLE_EQ(tl.scene_time(15), 4.0);
  EXPECT_DOUBLE_EQ(tl.scene_time(30), 3.0);
}

TEST_F(Parse, OddSizeIsFineWithoutVideo) {
  Timeline tl = load_timeline(all_scenes(), write(video_with("resolution = [63, 35]")), nullptr);
  EXPECT_EQ(tl.width, 63);
  EXPECT_NO_THROW(validate_overrides(tl, true));
}

// What resume, shards and verify compare: the parsed timeline, not its bytes.
TEST_F(Parse, ParsedHashIgnoresCommentsWhitespaceAndKeyOrderButNotValues) {
  const std::string a = "[video]\nscene = \"sdf_morph\"\nfps = 10\nduration = 1.0\n";
  const std::string b =
      "# a comment\n[video]\n  duration   =   1.0   # seconds\n\nfps = 10\nscene = \"sdf_morph\"\n";
  const std::string c = "[video]\nscene = \"sdf_morph\"\nfps = 10\nduration = 1.5\n";
  const Timeline ta = load_timeline(all_scenes(), write(a), nullptr);
  const Timeline tb = load_timeline(all_scenes(), write(b), nullptr);
  const Timeline tc = load_timeline(all_scenes(), write(c), nullptr);
  EXPECT_NE(ta.sha256, tb.sha256);
  EXPECT_EQ(ta.parsed_sha256, tb.parsed_sha256);
  EXPECT_NE(ta.parsed_sha256, tc.parsed_sha256);
  EXPECT_EQ(ta.parsed_sha256.size(), 64u);
}

}  // namespace
}  // namespace sdfreel
