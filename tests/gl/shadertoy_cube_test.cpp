// Cubes in a user's shader (docs/shaders.md): a cubemap channel read from six files or one cross
// reaches the shader as a samplerCube in GL's face order; Cube A draws each face with the site's
// rays and another pass samples it; a Cube A that reads itself has the same frames alone, in
// sequence and from a checkpoint; a bad cubemap exits 2 with nothing written.
#include <gtest/gtest.h>

#include <array>
#include <filesystem>

#include "gl/gl_cli_fixture.h"
#include "io/frame_files.h"
#include "io/png_file.h"

namespace sdfreel {
namespace {

namespace fs = std::filesystem;
using test::run_sdfreel;

// Column x of the picture samples the cube along +x, -x, +y, -y, +z, -z; column 6 shows
// iChannelResolution[0].x / 100.
const char* kSampleAxes =
    "void mainImage(out vec4 c, in vec2 p) {\n"
    "  vec3 d[6] = vec3[6](vec3(1, 0, 0), vec3(-1, 0, 0), vec3(0, 1, 0), vec3(0, -1, 0),\n"
    "                      vec3(0, 0, 1), vec3(0, 0, -1));\n"
    "  int x = int(p.x);\n"
    "  c = x < 6 ? texture(iChannel0, d[x]) : vec4(iChannelResolution[0].x / 100.0);\n"
    "}\n";

const uint8_t kFaceColour[6][3] = {{200, 0, 0}, {100, 0, 0}, {0, 200, 0},
                                   {0, 100, 0}, {0, 0, 200}, {0, 0, 100}};

class ShadertoyCube : public test::GlCliTest {
 protected:
  void write_timeline(const std::string& shader, const std::string& extra, int frames = 1) {
    test::write_file(dir + "/t.toml",
                     "[video]\nshader = \"" + shader +
                         "\"\nfps = 10\nduration = " + std::to_string(frames / 10.0) +
                         "\nresolution = [7, 2]\n\n[output]\ndir = \"out\"\n"
                         "frames = [\"png\"]\nvideo = \"\"\n" +
                         extra);
  }
  void write_png(const std::string& name, int w, int h, const std::vector<uint8_t>& rgb) {
    const std::vector<unsigned char> png = encode_png(w, h, 3, 8, rgb.data());
    test::write_file(dir + "/" + name, std::string(png.begin(), png.end()));
  }
  // Pixel (x, 0) of frame 0, channel c, 0..255.
  double pixel(int x, int c) {
    const ImageRGB16 img = read_png16(dir + "/out/frames/00000.png");
    return img.pixels[3 * size_t(x) + size_t(c)] / 65535.0 * 255.0;
  }
  void expect_face_colours() {
    for (int f = 0; f < 6; ++f)
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(pixel(f, c), kFaceColour[f][c], 0.01) << f;
  }
};

TEST_F(ShadertoyCube, SixFaceFilesArriveInGlsOrder) {
  std::string faces;
  for (int f = 0; f < 6; ++f) {
    std::vector<uint8_t> rgb;
    for (int i = 0; i < 4; ++i) rgb.insert(rgb.end(), kFaceColour[f], kFaceColour[f] + 3);
    write_png("face" + std::to_string(f) + ".png", 2, 2, rgb);
    faces += std::string(f ? ", " : "") + "\"face" + std::to_string(f) + ".png\"";
  }
  test::write_file(dir + "/axes.glsl", kSampleAxes);
  write_timeline("axes.glsl", "[channels.image]\niChannel0 = { cubemap = [" + faces + "] }\n");
  const test::RunResult r = run_sdfreel("render t.toml", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  expect_face_colours();
  EXPECT_NEAR(pixel(6, 0), 0.02 * 255.0, 0.01);  // iChannelResolution: 2 texels a face
}

TEST_F(ShadertoyCube, AHorizontalCrossGivesTheSameCube) {
  // 8x6 texels, 2x2 cells: +y above +z; -x +z +x -z across; -y below.
  const int cell_x[6] = {2, 0, 1, 1, 1, 3}, cell_y[6] = {1, 1, 0, 2, 1, 1};
  std::vector<uint8_t> rgb(8 * 6 * 3, 0);
  for (int f = 0; f < 6; ++f)
    for (int y = 0; y < 2; ++y)
      for (int x = 0; x < 2; ++x)
        std::copy(kFaceColour[f], kFaceColour[f] + 3,
                  &rgb[3 * (size_t(cell_y[f] * 2 + y) * 8 + size_t(cell_x[f] * 2 + x))]);
  write_png("cross.png", 8, 6, rgb);
  test::write_file(dir + "/axes.glsl", kSampleAxes);
  write_timeline("axes.glsl", "[channels.image]\niChannel0 = { cubemap = \"cross.png\" }\n");
  const test::RunResult r = run_sdfreel("render t.toml", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  expect_face_colours();
}

TEST_F(ShadertoyCube, CubeADrawsTheSitesRaysForAnotherPass) {
  fs::create_directories(dir + "/tabs");
  test::write_file(dir + "/tabs/cube_a.glsl",
                   "void mainCubemap(out vec4 c, in vec2 f, in vec3 ro, in vec3 rd) {\n"
                   "  c = vec4(0.5 + 0.5 * rd, 1.0);\n}\n");
  test::write_file(dir + "/tabs/image.glsl", kSampleAxes);
  test::write_file(dir + "/tabs/channels.toml", "[channels.image]\niChannel0 = \"cube_a\"\n");
  write_timeline("tabs", "[shader]\ncube_size = 16\n");
  const test::RunResult r = run_sdfreel("render t.toml", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  const double axis[6][3] = {{1, .5, .5}, {0, .5, .5}, {.5, 1, .5},
                             {.5, 0, .5}, {.5, .5, 1}, {.5, .5, 0}};
  for (int f = 0; f < 6; ++f)
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(pixel(f, c) / 255.0, axis[f][c], 0.03) << "face " << f << " channel " << c;
  EXPECT_NEAR(pixel(6, 0), 0.16 * 255.0, 0.01);  // iChannelResolution: cube_size
}

TEST_F(ShadertoyCube, CubeAWithFeedbackIsTheSameAloneInSequenceAndFromACheckpoint) {
  fs::create_directories(dir + "/tabs");
  test::write_file(
      dir + "/tabs/cube_a.glsl",
      "void mainCubemap(out vec4 c, in vec2 f, in vec3 ro, in vec3 rd) {\n"
      "  vec4 last = texture(iChannel0, rd);\n"
      "  c = vec4(fract(last.rgb + 0.13 * abs(rd) + 0.01 * float(iFrame)), 1.0);\n}\n");
  test::write_file(dir + "/tabs/image.glsl", kSampleAxes);
  test::write_file(dir + "/tabs/channels.toml",
                   "[channels.cube_a]\niChannel0 = \"self\"\n"
                   "[channels.image]\niChannel0 = \"cube_a\"\n");
  write_timeline("tabs", "[shader]\ncube_size = 8\ncheckpoint_every = 2\n", 6);
  ASSERT_EQ(run_sdfreel("render t.toml", dir).status, 0);
  const std::vector<std::string> all = test::framemd5_frame_lines(dir + "/out/frames.framemd5");
  ASSERT_EQ(all.size(), 6u);
  EXPECT_NE(all[4].substr(all[4].rfind(',')), all[5].substr(all[5].rfind(',')));
  EXPECT_TRUE(fs::exists(dir + "/out/checkpoints/buffers-00004.ckpt"));
  test::RunResult r = run_sdfreel("render t.toml --frames 5", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("from the checkpoint before frame 4"), std::string::npos) << r.err;
  EXPECT_EQ(test::framemd5_frame_lines(dir + "/out/frames.framemd5"), all);
  r = run_sdfreel("render t.toml --frames 5 --out alone", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("replaying the shader's buffers of frames 0-4"), std::string::npos);
  EXPECT_EQ(test::framemd5_frame_lines(dir + "/alone/frames.framemd5").at(0), all[5]);
}

TEST_F(ShadertoyCube, BadCubemapsExitTwoNamingTheFile) {
  write_png("square.png", 2, 2, std::vector<uint8_t>(12, 50));
  write_png("wide.png", 4, 2, std::vector<uint8_t>(24, 50));
  write_png("odd.png", 6, 5, std::vector<uint8_t>(90, 50));
  test::write_file(dir + "/axes.glsl", kSampleAxes);
  struct Case {
    std::string binding, message;
  };
  const Case cases[] = {
      {"\"odd.png\"", "image iChannel0: cubemap odd.png: a 6x5 image is neither a cross"},
      {"[\"square.png\", \"square.png\", \"square.png\", \"wide.png\", \"square.png\", "
       "\"square.png\"]",
       "face -y (wide.png) is 4x2: cube faces are square"},
      {"[\"square.png\", \"square.png\", \"square.png\", \"gone.png\", \"square.png\", "
       "\"square.png\"]",
       "image iChannel0: image file gone.png not found"},
      {"[\"square.png\", \"square.png\"]", "six faces in the order +x, -x, +y, -y, +z, -z, not 2"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.message);
    write_timeline("axes.glsl", "[channels.image]\niChannel0 = { cubemap = " + c.binding + " }\n");
    const test::RunResult r = run_sdfreel("render t.toml", dir);
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_NE(r.err.find("t.toml:12:"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir + "/out"));
  }
}

}  // namespace
}  // namespace sdfreel
