// Image files for a shader's channels, as Shadertoy hands them to a shader (docs/shaders.md): an
// 8-bit code reaches it as code / 255 exactly, sRGB-decoded only where the channel asks, 16-bit
// as code / 65535, floats as stored; gray files fill r, g and b. Any format OpenImageIO reads.
#include "shader/texture_file.h"

#include <gtest/gtest.h>

#include <fstream>

#include "io/exr_file.h"
#include "io/png_file.h"
#include "render/srgb.h"
#include "support/run.h"
#include "support/scratch.h"
#include "timeline/timeline.h"

namespace sdfreel {
namespace {

std::string write_png(const std::string& path, int w, int h, int channels, int bits,
                      const void* samples) {
  const std::vector<unsigned char> png = encode_png(w, h, channels, bits, samples);
  test::write_file(path, std::string(png.begin(), png.end()));
  return path;
}

TEST(TextureFile, EightBitCodesReachTheShaderAsCodeOver255) {
  const std::string dir = test::scratch_dir("texture_8bit");
  const uint8_t rgba[] = {0, 1, 51, 128, 200, 254, 255, 7};  // 2x1
  const ImageRGBA t = read_texture_file(write_png(dir + "/a.png", 2, 1, 4, 8, rgba), false);
  ASSERT_EQ(t.width, 2);
  ASSERT_EQ(t.height, 1);
  for (size_t i = 0; i < 8; ++i) EXPECT_EQ(t.pixels[i], float(rgba[i]) / 255.0f) << i;
}

TEST(TextureFile, SrgbDecodesColourButNotAlpha) {
  const std::string dir = test::scratch_dir("texture_srgb");
  const uint8_t rgba[] = {0, 51, 188, 128};
  const ImageRGBA t = read_texture_file(write_png(dir + "/a.png", 1, 1, 4, 8, rgba), true);
  for (size_t c = 0; c < 3; ++c) EXPECT_EQ(t.pixels[c], srgb_to_linear(float(rgba[c]) / 255.0f));
  EXPECT_NEAR(t.pixels[2], 0.5029, 1e-4);  // 188 is about half of linear light
  EXPECT_EQ(t.pixels[3], 128.0f / 255.0f);
}

TEST(TextureFile, SixteenBitCodesAndGrayFiles) {
  const std::string dir = test::scratch_dir("texture_16bit");
  // PNG stores big-endian samples; encode_png takes them in the machine's order.
  const uint16_t gray_alpha[] = {1000, 65535, 65535, 0};  // 2x1, gray + alpha
  const ImageRGBA t = read_texture_file(write_png(dir + "/ga.png", 2, 1, 2, 16, gray_alpha), false);
  for (size_t c = 0; c < 3; ++c) EXPECT_EQ(t.pixels[c], 1000.0f / 65535.0f);
  EXPECT_EQ(t.pixels[3], 1.0f);
  EXPECT_EQ(t.pixels[4 + 3], 0.0f);
  const uint8_t gray[] = {51};
  const ImageRGBA g = read_texture_file(write_png(dir + "/g.png", 1, 1, 1, 8, gray), false);
  EXPECT_EQ(g.pixels[0], 0.2f);
  EXPECT_EQ(g.pixels[1], 0.2f);
  EXPECT_EQ(g.pixels[2], 0.2f);
  EXPECT_EQ(g.pixels[3], 1.0f);
}

TEST(TextureFile, FloatFilesAreKeptAsStoredEvenWithSrgb) {
  const std::string dir = test::scratch_dir("texture_float");
  ImageRGBA hdr(1, 1);
  const float v[] = {3.5f, -0.25f, 1024.0f, 0.5f};  // exact in half
  std::copy(v, v + 4, hdr.pixels.begin());
  const std::vector<char> exr = encode_exr(hdr, {});
  test::write_file(dir + "/a.exr", std::string(exr.begin(), exr.end()));
  for (bool srgb : {false, true}) {
    const ImageRGBA t = read_texture_file(dir + "/a.exr", srgb);
    for (size_t c = 0; c < 4; ++c) EXPECT_EQ(t.pixels[c], v[c]) << c;
  }
}

TEST(TextureFile, ReadsJpegThroughOpenImageIO) {
  if (!test::have_tool("ffmpeg")) GTEST_SKIP() << "ffmpeg makes the JPEG; not installed";
  const std::string dir = test::scratch_dir("texture_jpeg");
  ASSERT_EQ(test::run("ffmpeg -v error -f lavfi -i color=c=0x3366cc:s=16x8 -frames:v 1 a.jpg", dir)
                .status,
            0);
  const ImageRGBA t = read_texture_file(dir + "/a.jpg", false);
  ASSERT_EQ(t.width, 16);
  ASSERT_EQ(t.height, 8);
  // A flat colour survives JPEG within a few codes.
  EXPECT_NEAR(t.pixels[0], 0x33 / 255.0, 4 / 255.0);
  EXPECT_NEAR(t.pixels[1], 0x66 / 255.0, 4 / 255.0);
  EXPECT_NEAR(t.pixels[2], 0xcc / 255.0, 4 / 255.0);
  EXPECT_EQ(t.pixels[3], 1.0f);
}

TEST(TextureFile, MissingOrUndecodableFilesNameThePath) {
  const std::string dir = test::scratch_dir("texture_bad");
  test::write_file(dir + "/broken.png", "\x89PNG\r\n\x1a\n not really");
  for (const std::string name : {"/nowhere.png", "/broken.png"}) {
    try {
      read_texture_file(dir + name, false);
      ADD_FAILURE() << name << " was read";
    } catch (const InputError& e) {
      EXPECT_EQ(e.file, dir + name);
      EXPECT_NE(std::string(e.what()).find("cannot read the image"), std::string::npos);
    }
  }
}

}  // namespace
}  // namespace sdfreel
