// A user's Shadertoy shader through the sdfreel binary on the GL backend (docs/shaders.md): the
// uniforms reach the pixels with Shadertoy's meaning, the output is display-referred (the PNG
// holds what the shader wrote), compile errors point at the user's file and line, and bad input
// exits 2 with nothing written.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "gl/gl_cli_fixture.h"
#include "io/frame_files.h"
#include "io/png_file.h"
#include "render/srgb.h"
#include "support/run.h"
#include "support/scratch.h"

namespace sdfreel {
namespace {

namespace fs = std::filesystem;
using test::run_sdfreel;

// Each pixel column x < 4 writes some uniforms, scaled into 0..1; the rest write fragCoord.
const char* kUniformShader = R"(// writes Shadertoy's uniforms into pixels
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  int x = int(fragCoord.x);
  if (x == 0) fragColor = vec4(iResolution.x / 100.0, iResolution.y / 100.0, iResolution.z, 0.25);
  else if (x == 1) fragColor = vec4(iTime / 10.0, float(iFrame) / 100.0, iTimeDelta, 1.0);
  else if (x == 2) fragColor = vec4(iFrameRate / 100.0, iMouse.x / 100.0, -iMouse.w / 100.0, 1.0);
  else if (x == 3) fragColor = vec4(iChannelTime[0] / 10.0, iDate.x / 4000.0, iSampleRate / 1e5, 1.0);
  else fragColor = vec4(fragCoord / 100.0, 0.0, 1.0);
}
)";

class Shadertoy : public test::GlCliTest {
 protected:
  // A timeline beside `shader` (written as mine.glsl); `extra` appended.
  std::string write(const std::string& shader, const std::string& extra = "") {
    test::write_file(dir + "/mine.glsl", shader);
    test::write_file(dir + "/t.toml",
                     "[video]\nshader = \"mine.glsl\"\nfps = 10\nduration = 0.3\n"
                     "resolution = [8, 4]\n\n[output]\ndir = \"out\"\nframes = [\"png\"]\n"
                     "video = \"\"\n" +
                         extra);
    return dir + "/t.toml";
  }
  // The 16-bit display value of pixel (x, y) of frame `frame`, channel c, as 0..1.
  double pixel(int frame, int x, int y, int c) {
    const std::string name = std::to_string(frame);
    const ImageRGB16 img =
        read_png16(dir + "/out/frames/" + std::string(5 - name.size(), '0') + name + ".png");
    return img.pixels[3 * (size_t(y) * size_t(img.width) + size_t(x)) + size_t(c)] / 65535.0;
  }
};

constexpr double kStep = 1.0 / 65535.0;  // one step of the 16-bit PNG

TEST_F(Shadertoy, UniformsReachThePixelsWithShadertoysMeaning) {
  write(kUniformShader, "\n[params]\niMouse = [40.0, 10.0, 20.0, -30.0]\n");
  const test::RunResult r = run_sdfreel("render t.toml", dir);  // gl by default for a shader
  ASSERT_EQ(r.status, 0) << r.err;
  for (int f = 0; f < 3; ++f) {
    SCOPED_TRACE("frame " + std::to_string(f));
    EXPECT_NEAR(pixel(f, 0, 0, 0), 0.08, kStep);  // iResolution (8, 4, 1)
    EXPECT_NEAR(pixel(f, 0, 0, 1), 0.04, kStep);
    EXPECT_NEAR(pixel(f, 0, 0, 2), 1.0, kStep);
    EXPECT_NEAR(pixel(f, 1, 0, 0), 0.1 * f / 10.0, kStep);  // iTime = f / fps
    EXPECT_NEAR(pixel(f, 1, 0, 1), f / 100.0, kStep);       // iFrame from 0
    EXPECT_NEAR(pixel(f, 1, 0, 2), 0.1, kStep);             // iTimeDelta = 1 / fps
    EXPECT_NEAR(pixel(f, 2, 0, 0), 0.1, kStep);             // iFrameRate
    EXPECT_NEAR(pixel(f, 2, 0, 1), 0.4, kStep);             // iMouse from [params]
    EXPECT_NEAR(pixel(f, 2, 0, 2), 0.3, kStep);
    EXPECT_NEAR(pixel(f, 3, 0, 0), 0.1 * f / 10.0, kStep);   // iChannelTime: the shader's time
    EXPECT_NEAR(pixel(f, 3, 0, 1), 2026.0 / 4000.0, kStep);  // iDate from the timeline, not now
    EXPECT_NEAR(pixel(f, 3, 0, 2), 0.441, kStep);            // iSampleRate 44100
    // fragCoord is the pixel centre, counted from the bottom row as on Shadertoy.
    EXPECT_NEAR(pixel(f, 5, 0, 0), 0.055, kStep);
    EXPECT_NEAR(pixel(f, 5, 0, 1), 0.035, kStep);
    EXPECT_NEAR(pixel(f, 5, 3, 1), 0.005, kStep);
  }
}

TEST_F(Shadertoy, TheTimelinesCameraAndParamsReachTheShader) {
  write(
      "uniform float speed = 1.0;\n"
      "uniform vec3 tint;\n"
      "void mainImage(out vec4 c, in vec2 p) {\n"
      "  int x = int(p.x);\n"
      "  vec3 centre = normalize(iCameraToWorld * vec3(0.0, 0.0, iCameraFocal));\n"
      "  if (x == 0) c = vec4(iCameraPosition * 0.1 + 0.5, 1.0);\n"
      "  else if (x == 1) c = vec4(iCameraFov / 100.0, iCameraFocal / 10.0, speed / 10.0, 1.0);\n"
      "  else if (x == 2) c = vec4(centre * 0.5 + 0.5, 1.0);\n"
      "  else if (x == 3) c = vec4(iCameraTarget * 0.1 + 0.5, 1.0);\n"
      "  else if (x == 4) c = vec4(iCameraUp * 0.5 + 0.5, 1.0);\n"
      "  else c = vec4(tint, 1.0);\n"
      "}\n",
      "\n[camera]\nkeys = [{ t = 0.0, position = [1.0, 2.0, -3.0], target = [0.0, 1.0, 0.0], "
      "fov = 60.0 }]\n\n[params]\ntint = [0.1, 0.2, 0.3]\n\n[params.speed]\n"
      "keys = [[0.0, 2.0], [0.2, 4.0]]\n");
  const test::RunResult r = run_sdfreel("render t.toml", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  const double position[3] = {1.0, 2.0, -3.0}, target[3] = {0.0, 1.0, 0.0};
  double forward[3], length = 0.0;
  for (int i = 0; i < 3; ++i)
    forward[i] = target[i] - position[i], length += forward[i] * forward[i];
  for (int i = 0; i < 3; ++i) {
    SCOPED_TRACE("component " + std::to_string(i));
    EXPECT_NEAR(pixel(0, 0, 0, i), position[i] * 0.1 + 0.5, kStep);
    EXPECT_NEAR(pixel(0, 2, 0, i), forward[i] / std::sqrt(length) * 0.5 + 0.5, 2 * kStep);
    EXPECT_NEAR(pixel(0, 3, 0, i), target[i] * 0.1 + 0.5, kStep);
    EXPECT_NEAR(pixel(0, 5, 0, i), 0.1 * (i + 1), kStep);  // a vec3 parameter
  }
  EXPECT_NEAR(pixel(0, 1, 0, 0), 0.6, kStep);                                // fov
  EXPECT_NEAR(pixel(0, 1, 0, 1), 1.0 / std::tan(M_PI / 6.0) / 10.0, kStep);  // focal
  EXPECT_GT(pixel(0, 4, 0, 1), 0.5 + 0.4);                                   // up: mostly +y
  // An animated parameter: 2 at t = 0, 3 at t = 0.1, 4 at t = 0.2 (linear keys).
  for (int f = 0; f < 3; ++f) EXPECT_NEAR(pixel(f, 1, 0, 2), (2.0 + f) / 10.0, kStep);
}

TEST_F(Shadertoy, TimeDeltaFollowsTheTimeCurveAndFrameStaysTheFrameNumber) {
  // TIME runs at twice the video's speed: iTime 0, 0.2, 0.4 and iTimeDelta 0.2; iFrame 0, 1, 2.
  write(kUniformShader, "\n[time]\nkeys = [[0.0, 0.0], [1.0, 2.0]]\n");
  const test::RunResult r = run_sdfreel("render t.toml", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  for (int f = 0; f < 3; ++f) {
    SCOPED_TRACE("frame " + std::to_string(f));
    EXPECT_NEAR(pixel(f, 1, 0, 0), 0.2 * f / 10.0, kStep);
    EXPECT_NEAR(pixel(f, 1, 0, 1), f / 100.0, kStep);
    EXPECT_NEAR(pixel(f, 1, 0, 2), 0.2, kStep);
  }
}

TEST_F(Shadertoy, OutputIsDisplayReferredAndAlphaIsOne) {
  write("void mainImage(out vec4 c, in vec2 p) { c = vec4(0.25, 0.5, 0.75, 0.0); }\n");
  const test::RunResult r = run_sdfreel("render t.toml", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  // No view transform on top: the PNG holds the shader's numbers.
  EXPECT_NEAR(pixel(0, 3, 2, 0), 0.25, kStep);
  EXPECT_NEAR(pixel(0, 3, 2, 1), 0.5, kStep);
  EXPECT_NEAR(pixel(0, 3, 2, 2), 0.75, kStep);
}

TEST_F(Shadertoy, ShaderTableSetsTheDateTheSampleRateAndALinearOutput) {
  write(kUniformShader, "\n[shader]\ndate = [2000, 5, 2, 30]\nsample_rate = 48000\n");
  test::RunResult r = run_sdfreel("render t.toml", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NEAR(pixel(0, 3, 0, 1), 2000.0 / 4000.0, kStep);
  EXPECT_NEAR(pixel(0, 3, 0, 2), 0.48, kStep);
  // Linear output: the [color] view makes the display pixels, so 0.5 is not shown as 0.5.
  write("void mainImage(out vec4 c, in vec2 p) { c = vec4(0.5); }\n",
        "\n[shader]\noutput = \"linear\"\n");
  r = run_sdfreel("render t.toml", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_GT(std::abs(pixel(0, 0, 0, 0) - 0.5), 0.02);
}

TEST_F(Shadertoy, DisplayOutputNeedsThePngFrames) {
  test::write_file(dir + "/mine.glsl",
                   "void mainImage(out vec4 c, in vec2 p) { c = vec4(1.0); }\n");
  test::write_file(dir + "/t.toml",
                   "[video]\nshader = \"mine.glsl\"\n\n[output]\ndir = \"out\"\n"
                   "frames = [\"exr\"]\n");
  const test::RunResult r = run_sdfreel("render t.toml", dir);
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("t.toml:6:10: error: output.frames of a display-referred shader must "
                       "include \"png\""),
            std::string::npos)
      << r.err;
  EXPECT_FALSE(fs::exists(dir + "/out"));
}

TEST_F(Shadertoy, SamplesMoveFragCoordWithinThePixel) {
  // The square of fragCoord's fraction: 0.25 at the centre (one sample); with 4 samples spread
  // over the pixel the mean of the squares is larger, and below 1.
  write("void mainImage(out vec4 c, in vec2 p) { float f = fract(p.x); c = vec4(f * f); }\n");
  ASSERT_EQ(run_sdfreel("render t.toml", dir).status, 0);
  EXPECT_NEAR(pixel(0, 2, 2, 0), 0.25, kStep);
  const test::RunResult r = run_sdfreel("render t.toml --samples 4", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_GT(pixel(0, 2, 2, 0), 0.25 + 0.01);
  EXPECT_LT(pixel(0, 2, 2, 0), 1.0);
}

TEST_F(Shadertoy, CompileErrorNamesTheUsersFileLineAndColumn) {
  write(
      "// line 1\n"
      "void mainImage(out vec4 fragColor, in vec2 fragCoord) {\n"
      "  vec3 c = vec3(1.0);\n"
      "  fragColor = vec4(c, undefined_name);\n"
      "}\n");
  const test::RunResult r = run_sdfreel("render t.toml", dir);
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("mine.glsl:4:"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("undefined_name"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir + "/out")) << "nothing is written for a shader that fails";
}

TEST_F(Shadertoy, BadInputExitsTwoWithNothingWritten) {
  struct Case {
    std::string shader, extra, args, message;
  };
  const Case cases[] = {
      {"void main() {}\n", "", "", "no mainImage function"},
      {"void mainImage(out vec4 c, in vec2 p) { c = vec4(1.0); }\n", "", "--backend cpu",
       "runs on the GL backend only"},
      {"void mainImage(out vec4 c, in vec2 p) { c = vec4(1.0); }\n", "\n[params]\nspeed = 2.0\n",
       "", "speed"},
      {"uniform float speed;\nvoid mainImage(out vec4 c, in vec2 p) { c = vec4(speed); }\n",
       "\n[params]\nsped = 2.0\n", "", "did you mean 'speed'"},
      {"uniform float iTime;\nvoid mainImage(out vec4 c, in vec2 p) { c = vec4(1.0); }\n", "", "",
       "declared by sdfreel already"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.message);
    write(c.shader, c.extra);
    const test::RunResult r = run_sdfreel("render t.toml " + c.args, dir);
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir + "/out"));
  }
  // A shader file that is not there, named by the timeline.
  test::write_file(dir + "/t.toml", "[video]\nshader = \"nowhere.glsl\"\n");
  const test::RunResult r = run_sdfreel("render t.toml", dir);
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("nowhere.glsl"), std::string::npos) << r.err;
}

TEST_F(Shadertoy, ResumeKeepsNoFrameOfAnEditedShader) {
  write("void mainImage(out vec4 c, in vec2 p) { c = vec4(0.5); }\n");
  ASSERT_EQ(run_sdfreel("render t.toml", dir).status, 0);
  const test::RunResult same = run_sdfreel("render t.toml --resume", dir);
  ASSERT_EQ(same.status, 0) << same.err;
  EXPECT_EQ(same.err.find("done in"), std::string::npos) << "nothing to render: " << same.err;
  // The shader's code is part of the manifest (versions: shader_sha256), not only the timeline.
  test::write_file(dir + "/mine.glsl",
                   "void mainImage(out vec4 c, in vec2 p) { c = vec4(0.25); }\n");
  const test::RunResult edited = run_sdfreel("render t.toml --resume", dir);
  ASSERT_EQ(edited.status, 0) << edited.err;
  EXPECT_NE(edited.err.find("frame 3/3 done"), std::string::npos) << edited.err;
  EXPECT_NEAR(pixel(2, 0, 0, 0), 0.25, kStep);
}

TEST_F(Shadertoy, TextureChannelsReadPngFilesUprightUnlessUnflipped) {
  // 1x2: the top row red, the bottom row green (8-bit, so 0.2 is 51).
  const uint8_t rgb[] = {255, 51, 0, 0, 255, 0};
  const std::vector<unsigned char> png = encode_png(1, 2, 3, 8, rgb);
  test::write_file(dir + "/red_over_green.png", std::string(png.begin(), png.end()));
  // Left half samples the texture's upper half, right half its lower half (nearest).
  const char* shader =
      "void mainImage(out vec4 c, in vec2 p) {\n"
      "  c = texture(iChannel0, vec2(0.5, p.x < 4.0 ? 0.75 : 0.25));\n"
      "}\n";
  write(shader,
        "\n[channels.image]\niChannel0 = { texture = \"red_over_green.png\", filter = "
        "\"nearest\" }\n");
  test::RunResult r = run_sdfreel("render t.toml", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NEAR(pixel(0, 0, 0, 0), 1.0, kStep);  // upright: the top of the picture is red
  EXPECT_NEAR(pixel(0, 0, 0, 1), 0.2, kStep);  // the file's numbers, no sRGB decoding
  EXPECT_NEAR(pixel(0, 7, 0, 1), 1.0, kStep);
  write(shader,
        "\n[channels.image]\niChannel0 = { texture = \"red_over_green.png\", filter = "
        "\"nearest\", vflip = false }\n");
  r = run_sdfreel("render t.toml", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NEAR(pixel(0, 0, 0, 1), 1.0, kStep);  // upside down, as WebGL uploads it
  EXPECT_NEAR(pixel(0, 7, 0, 0), 1.0, kStep);
}

TEST_F(Shadertoy, NonFinitePixelsAreWrittenBlackWithAWarning) {
  write(
      "void mainImage(out vec4 c, in vec2 p) {\n"
      "  float zero = p.x - p.x;\n"
      "  c = p.x < 2.0 ? vec4(zero / zero) : vec4(0.5);\n"
      "}\n");
  const test::RunResult r = run_sdfreel("render t.toml", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("NaN or infinite values written as 0"), std::string::npos) << r.err;
  EXPECT_EQ(pixel(0, 0, 0, 0), 0.0);
  EXPECT_NEAR(pixel(0, 4, 0, 0), 0.5, kStep);
  // Strict: the frame fails (exit 1) and is never written.
  test::write_file(dir + "/t.toml",
                   test::read_file(dir + "/t.toml") + "\n[shader]\nnon_finite = \"error\"\n");
  fs::remove_all(dir + "/out");
  const test::RunResult strict = run_sdfreel("render t.toml", dir);
  EXPECT_EQ(strict.status, 1) << strict.err;
  EXPECT_NE(strict.err.find("frame 0: pixel (0, 0) channel R is NaN"), std::string::npos)
      << strict.err;
  EXPECT_FALSE(fs::exists(dir + "/out/frames/00000.png"));
}

TEST_F(Shadertoy, SrgbChannelsDecodeTheirTexels) {
  const uint8_t rgb[] = {188, 51, 0};
  const std::vector<unsigned char> png = encode_png(1, 1, 3, 8, rgb);
  test::write_file(dir + "/one.png", std::string(png.begin(), png.end()));
  const char* shader =
      "void mainImage(out vec4 c, in vec2 p) { c = texture(iChannel1, vec2(0.5)); }\n";
  write(shader, "\n[channels.image]\niChannel1 = { texture = \"one.png\", srgb = true }\n");
  const test::RunResult r = run_sdfreel("render t.toml", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NEAR(pixel(0, 3, 2, 0), srgb_to_linear(188.0f / 255.0f), kStep);
  EXPECT_NEAR(pixel(0, 3, 2, 1), srgb_to_linear(0.2f), kStep);
  write(shader, "\n[channels.image]\niChannel1 = { texture = \"one.png\" }\n");
  ASSERT_EQ(run_sdfreel("render t.toml", dir).status, 0);
  EXPECT_NEAR(pixel(0, 3, 2, 0), 188.0 / 255.0, kStep);  // as stored: Shadertoy's default
}

TEST_F(Shadertoy, BadImageFilesExitTwoNamingThePassAndChannel) {
  test::write_file(dir + "/broken.jpg", "\xff\xd8\xff not a JPEG");
  const char* shader = "void mainImage(out vec4 c, in vec2 p) { c = texture(iChannel2, p); }\n";
  for (const std::string file : {"broken.jpg", "nowhere.png"}) {
    SCOPED_TRACE(file);
    write(shader, "\n[channels.image]\niChannel2 = { texture = \"" + file + "\" }\n");
    const test::RunResult r = run_sdfreel("render t.toml", dir);
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_NE(r.err.find("t.toml:13:13: error: image iChannel2"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(file), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir + "/out"));
  }
}

// OpenImageIO (some 250 shared libraries) is opened only by a timeline that binds an image.
TEST_F(Shadertoy, OpenImageIOIsLoadedOnlyForImageChannels) {
  const uint8_t rgb[] = {1, 2, 3};
  const std::vector<unsigned char> png = encode_png(1, 1, 3, 8, rgb);
  test::write_file(dir + "/one.png", std::string(png.begin(), png.end()));
  const char* shader = "void mainImage(out vec4 c, in vec2 p) { c = texture(iChannel0, p); }\n";
  write(shader);
  test::RunResult r = run_sdfreel("render t.toml --frames 0", dir, "LD_DEBUG=files ");
  ASSERT_EQ(r.status, 0) << r.err.substr(0, 2000);
  EXPECT_EQ(r.err.find("libOpenImageIO"), std::string::npos);
  write(shader, "\n[channels.image]\niChannel0 = { texture = \"one.png\" }\n");
  r = run_sdfreel("render t.toml --frames 0", dir, "LD_DEBUG=files ");
  ASSERT_EQ(r.status, 0) << r.err.substr(0, 2000);
  EXPECT_NE(r.err.find("libOpenImageIO"), std::string::npos);
}

}  // namespace
}  // namespace sdfreel
