// One test per rule of docs/timeline.md "What is refused": the message and where it points.
#include <gtest/gtest.h>

#include "scenes/registry.h"
#include "timeline/fixture.h"

namespace sdfreel {
namespace {

using testing::video_with;

class BadInput : public testing::TimelineFiles {};

TEST_F(BadInput, TomlSyntaxError) {
  expect_error(video_with("fps = = 30"), "", 3, 7);
  // An unterminated string, at the line end and at the end of the file: say what to add.
  expect_error("[video]\nscene = \"sdf_morph\n",
               "a string is not closed: add the missing closing quote", 2, 19);
  expect_error("[video]\nscene = \"sdf_morph", "a string is not closed", 2, 19);
}

TEST_F(BadInput, UnknownTableSuggestsTheClosest) {
  expect_error("[video]\nscene = \"sdf_morph\"\n[camrea]\n",
               "unknown table 'camrea'; did you mean 'camera'?", 3, 2);
  expect_error("[video]\nscene = \"sdf_morph\"\n[lights]\n", "unknown table 'lights'", 3, 2);
}

TEST_F(BadInput, UnknownKeySuggestsTheClosest) {
  expect_error(video_with("fsp = 30"), "unknown key 'fsp' in [video]; did you mean 'fps'?", 3, 1);
  expect_error(video_with("[output]\ncodek = \"h264\""),
               "unknown key 'codek' in [output]; did you mean 'codec'?", 4, 1);
  expect_error(video_with("[camera]\nkeys = [{ t = 0, position = [0, 0, 1], target = [0, 0, 0], "
                          "fvo = 30 }]"),
               "unknown key 'fvo' in camera.keys[0]; did you mean 'fov'?", 4, 60);
}

TEST_F(BadInput, KeyOutsideItsTableNamesTheTable) {
  expect_error("scene = \"sdf_morph\"\nfps = 30\n",
               "key 'scene' is outside every table: it belongs under [video] (a key goes below "
               "its table's header line)",
               1, 1);
  expect_error("video = \"v.mp4\"\n",
               "key 'video' is outside every table: it belongs under [output]", 1, 1);
  expect_error("keys = []\n[video]\nscene = \"sdf_morph\"\n",
               "it belongs under [camera], [time] or a [params.NAME] table", 1, 1);
}

TEST_F(BadInput, MissingScene) {
  expect_error("[video]\nfps = 30\n", "missing key 'scene' in [video]", 1, 1);
  expect_error("[output]\ndir = \"x\"\n", "missing table [video]", 0, 0);
}

TEST_F(BadInput, WrongTypes) {
  expect_error(video_with("samples = \"4\""), "video.samples must be an integer, not a string", 3,
               11);
  expect_error(video_with("duration = \"12\""), "video.duration must be a number, not a string", 3,
               12);
  expect_error(video_with("resolution = [1280.0, 720]"),
               "video.resolution must be an array of two integers", 3, 14);
  expect_error(video_with("fps = 29.97"), "video.fps must be an integer or a rational string", 3,
               7);
  expect_error(video_with("fps = true"), "rational string such as \"30000/1001\", not a boolean", 3,
               7);
  expect_error("video = 3\n", "video must be a table, not an integer", 1, 9);
  expect_error(video_with("[camera]\nkeys = [{ t = 0, position = [0, 0], target = [0, 0, 0] }]"),
               "camera.keys[0].position must be an array of 3 numbers, not of 2", 4, 29);
  expect_error(video_with("[time]\nkeys = [[0, 0], [1]]"), "time.keys[1] must be a [t, value] pair",
               4, 17);
  expect_error(video_with("[params]\ncolor = 0.5"),
               "params.color must be an array of 3 numbers, not a float", 4, 9);
}

TEST_F(BadInput, KeyTimesMustStrictlyIncrease) {
  expect_error(video_with("[time]\nkeys = [[0, 0], [2, 1], [2, 3]]"),
               "time.keys[2]: t = 2 is not after the previous key's t = 2", 4, 26);
  expect_error(video_with("[params.reflectivity]\nkeys = [[1, 0.5], [0.5, 0.2]]"),
               "params.reflectivity.keys[1]: t = 0.5 is not after the previous key's t = 1", 4, 20);
  expect_error(video_with("[camera]\nkeys = [\n"
                          "{ t = 3, position = [0, 0, 1], target = [0, 0, 0] },\n"
                          "{ t = 1, position = [0, 0, 2], target = [0, 0, 0] },\n]"),
               "camera.keys[1]: t = 1 is not after the previous key's t = 3", 6, 7);
}

TEST_F(BadInput, NanAndInfinity) {
  expect_error(video_with("duration = nan"), "video.duration must be a finite number, not nan", 3,
               12);
  expect_error(
      video_with("[camera]\nkeys = [{ t = 0, position = [0, inf, 1], target = [0, 0, 0] }]"),
      "camera.keys[0].position[1] must be a finite number, not inf", 4, 33);
  expect_error(video_with("[time]\nkeys = [[0, 0], [-inf, 1]]"),
               "time.keys[1] t must be a finite number, not -inf", 4, 18);
}

TEST_F(BadInput, FpsMustBePositive) {
  expect_error(video_with("fps = 0"), "video.fps must be > 0", 3, 7);
  expect_error(video_with("fps = -24"), "video.fps must be > 0", 3, 7);
  expect_error(video_with("fps = \"0/1001\""), "video.fps must be > 0", 3, 7);
  expect_error(video_with("fps = \"30/0\""), "divides by zero", 3, 7);
  expect_error(video_with("fps = \"-30/-1\""), "video.fps must be > 0", 3, 7);
  expect_error(video_with("fps = \"thirty\""), "is not a rational number", 3, 7);
}

TEST_F(BadInput, DurationMustBePositive) {
  expect_error(video_with("duration = 0"), "video.duration must be > 0, got 0", 3, 12);
  expect_error(video_with("duration = -1.5"), "video.duration must be > 0, got -1.5", 3, 12);
}

TEST_F(BadInput, ResolutionRange) {
  expect_error(video_with("resolution = [0, 720]"), "resolution 0x720 is outside 1..16384", 3, 14);
  expect_error(video_with("resolution = [1280, 16385]"),
               "resolution 1280x16385 is outside 1..16384", 3, 14);
  expect_error(video_with("resolution = [1280]"), "must be an array of two integers", 3, 14);
}

TEST_F(BadInput, FovOutsideOpenRange) {
  const std::string key = "[camera]\nkeys = [{ t = 0, position = [0, 0, 1], target = [0, 0, 0], ";
  expect_error(video_with(key + "fov = 180 }]"),
               "camera.keys[0].fov 180 is outside (0, 180) degrees", 4, 66);
  expect_error(video_with(key + "fov = 0 }]"), "camera.keys[0].fov 0 is outside (0, 180)", 4, 66);
}

TEST_F(BadInput, CameraPositionEqualsTarget) {
  expect_error(video_with("[camera]\nkeys = [{ t = 0, position = [1, 2, 3], target = [1, 2, 3] }]"),
               "camera.keys[0]: position equals target", 4, 49);
}

TEST_F(BadInput, UnknownScene) {
  expect_error("[video]\nscene = \"sdf_mroph\"\n",
               "unknown scene 'sdf_mroph'; did you mean 'sdf_morph'?", 2, 9);
  expect_error("[video]\nscene = \"teapot\"\n", "unknown scene 'teapot' (known scenes: ", 2, 9);
}

TEST_F(BadInput, UnknownParameter) {
  expect_error(video_with("[params]\nreflectivty = 0.5"),
               "unknown parameter 'reflectivty' for scene 'sdf_morph'; did you mean "
               "'reflectivity'?",
               4, 1);
  expect_error(video_with("[params.glow]\nkeys = [[0, 1]]"),
               "unknown parameter 'glow' for scene 'sdf_morph'", 3, 9);
}

TEST_F(BadInput, ParameterValueOutsideItsRange) {
  expect_error(video_with("[params]\nreflectivity = 1.5"),
               "params.reflectivity 1.5 is outside the range of reflectivity, 0..1", 4, 16);
  expect_error(video_with("[params]\ncolor = [0.5, -0.1, 0.5]"),
               "params.color -0.1 is outside the range of color, 0..1", 4, 9);
  expect_error(
      video_with("[params.morph_period]\nkeys = [[0, 6], [5, 200]]"),
      "params.morph_period.keys[1] value 200 is outside the range of morph_period, 0.5..120", 4,
      21);
}

TEST_F(BadInput, ParameterComponentCount) {
  expect_error(video_with("[params]\ncolor = [0.5, 0.5]"),
               "params.color must be an array of 3 numbers, not of 2", 4, 9);
  expect_error(video_with("[params]\nreflectivity = [0.5]"),
               "params.reflectivity must be a number, not an array", 4, 16);
}

TEST_F(BadInput, UnknownCodec) {
  expect_error(
      video_with("[output]\ncodec = \"x264\""),
      "unknown codec 'x264': use h264, h264-10bit, hevc, hevc-10bit, vp9, av1, ffv1, prores, webp "
      "or gif; did you mean 'h264'?",
      4, 9);
}

// Knows one config ("builtin") with one display ("sRGB") with one view ("Standard").
struct OneViewChecker : ColorChecker {
  std::string check(const std::string& config, const std::string& display,
                    const std::string& view) const override {
    if (config != "builtin") return "OCIO config \"" + config + "\": file not found";
    if (display != "sRGB") return "config 'builtin' has no display '" + display + "'";
    if (view != "Standard") return "display 'sRGB' has no view '" + view + "'";
    return "";
  }
};

TEST_F(BadInput, UnknownDisplayOrView) {
  OneViewChecker color;
  expect_error(video_with("[color]\ndisplay = \"P3\"\nview = \"Standard\""),
               "config 'builtin' has no display 'P3'", 4, 11, &color);
  expect_error(video_with("[color]\nconfig = \"studio.ocio\"\nview = \"Standard\""),
               "OCIO config \"studio.ocio\": file not found", 4, 10, &color);
  // The defaults are checked too: the error points at [color] when it exists.
  expect_error(video_with("[color]\nconfig = \"builtin\""), "has no view 'ACES 1.0 - SDR Video'", 3,
               1, &color);
  expect_error(video_with(""), "has no view", 0, 0, &color);
  expect_error(video_with("[color]\ndisplay = \"sRGB\"\nview = \"Raw\""),
               "display 'sRGB' has no view 'Raw'", 5, 8, &color);
  // Without a checker the color names are not checked.
  EXPECT_NO_THROW(
      load_timeline(all_scenes(), write(video_with("[color]\ndisplay = \"P3\"")), nullptr));
}

// The file parses (a still or --no-video takes any size); the render that makes the video refuses,
// pointing at [video] resolution.
TEST_F(BadInput, OddSizeWithH264NamesTheNearestEvenSize) {
  const Timeline tl = load_timeline(
      all_scenes(), write(video_with("resolution = [63, 35]\n[output]\nvideo = \"a.mp4\"")),
      nullptr);
  try {
    validate_overrides(tl, true);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(
                  "codec h264 (yuv420p) needs an even width and height: use 64x36"),
              std::string::npos)
        << e.what();
    EXPECT_EQ(e.line, 3);
    EXPECT_EQ(e.column, 14);
  }
  EXPECT_NO_THROW(validate_overrides(tl, false));
  // Other codecs take odd sizes.
  EXPECT_NO_THROW(validate_overrides(
      load_timeline(
          all_scenes(),
          write(video_with("resolution = [63, 35]\n[output]\nvideo = \"a.mkv\"\ncodec = \"ffv1\"")),
          nullptr),
      true));
}

TEST_F(BadInput, SamplesRange) {
  expect_error(video_with("samples = 0"), "samples 0 is outside 1..1024", 3, 11);
  expect_error(video_with("samples = 1025"), "samples 1025 is outside 1..1024", 3, 11);
}

TEST_F(BadInput, UnknownQuality) {
  expect_error(video_with("quality = \"fianl\""),
               "video.quality 'fianl' is not one of draft, final or reference; did you mean "
               "'final'?",
               3, 11);
}

TEST_F(BadInput, UnknownInterpolation) {
  expect_error(video_with("[time]\ninterpolation = \"smoth\"\nkeys = [[0, 0]]"),
               "time.interpolation 'smoth' is not one of step, linear, smooth or catmull-rom; did "
               "you mean 'smooth'?",
               4, 17);
  expect_error(video_with("[camera]\ninterpolation = \"bezier\""),
               "camera.interpolation 'bezier' is not one of", 4, 17);
  expect_error(video_with("[params.reflectivity]\ninterpolation = \"cubic\"\nkeys = [[0, 0]]"),
               "params.reflectivity.interpolation 'cubic'", 4, 17);
}

TEST_F(BadInput, UnknownSpeed) {
  expect_error(video_with("[camera]\nspeed = \"fast\""),
               "camera.speed 'fast' is not one of keys or constant", 4, 9);
}

TEST_F(BadInput, CrfRange) {
  expect_error(video_with("[output]\ncrf = 52"), "output.crf 52 is outside 0..51", 4, 7);
  expect_error(video_with("[output]\ncrf = -1"), "output.crf -1 is outside 0..51", 4, 7);
}

// Any lower-case extension parses: whether OpenImageIO writes it is checked when the command
// starts (tests/formats).
TEST_F(BadInput, UnknownFrameFormat) {
  expect_error(video_with("[output]\nframes = [\"exr\", \".jpg\"]"),
               "output.frames[1] = \".jpg\": name a frame format by its file extension in lower "
               "case",
               4, 18);
  expect_error(video_with("[output]\ntiff_bits = 24"), "output.tiff_bits = 24: use 8, 16 or 32", 4,
               13);
  expect_error(video_with("[output]\njpeg_quality = 0"), "output.jpeg_quality 0 is outside 1..100",
               4, 16);
}

// [output] passes: known names, each once, that the scene gives, into EXR frames.
TEST_F(BadInput, CompositingPasses) {
  expect_error(video_with("[output]\npasses = [\"sampels\"]"),
               "unknown pass 'sampels': use samples, sdf_evals, id, depth or normal", 4, 11);
  expect_error(video_with("[output]\npasses = [\"samples\", \"samples\"]"),
               "pass 'samples' is named twice", 4, 22);
  expect_error(video_with("[output]\nframes = [\"png\"]\npasses = [\"samples\"]"),
               "output.passes are channels of the EXR frames: add \"exr\" to output.frames", 5, 10);
  expect_error("[video]\nscene = \"fur\"\n[output]\npasses = [\"samples\", \"sdf_evals\"]\n",
               "scene 'fur' gives no 'sdf_evals' pass (it gives samples, id, depth and normal)", 4, 22);
  const Timeline tl = load_timeline(
      all_scenes(), write(video_with("[output]\npasses = [\"sdf_evals\", \"samples\"]")), nullptr);
  EXPECT_EQ(tl.frame_options.passes, (std::vector<std::string>{"sdf_evals", "samples"}));
}

TEST_F(BadInput, NotUtf8) {
  expect_error("[video]\nscene = \"sdf\xff\"\n", "the file is not valid UTF-8", 2, 13);
}

TEST_F(BadInput, LargerThan16MiB) {
  std::string text = video_with("");
  text += std::string((16u << 20) - text.size() + 1, '#');  // one comment, one byte too many
  expect_error(text, "larger than 16 MiB", 0, 0);
  // Exactly 16 MiB is still read.
  text.pop_back();
  EXPECT_NO_THROW(load_timeline(all_scenes(), write(text), nullptr));
}

TEST_F(BadInput, MissingFile) {
  EXPECT_THROW(load_timeline(all_scenes(), (dir_ / "absent.toml").string(), nullptr), InputError);
}

}  // namespace
}  // namespace sdfreel
