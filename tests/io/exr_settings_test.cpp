// EXR settings of [output]: each compression and channel type, read back with OpenEXR; the
// header carries the chromaticities of the scene-linear space (Rec.709 primaries, D65).
#include <Imath/half.h>
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfStandardAttributes.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "io/exr_file.h"
#include "io/frame_files.h"
#include "support/scratch.h"
#include "timeline/frame_file_options.h"

namespace sdfreel {
namespace {

// A frame with smooth gradients and values above 1, as scenes give.
ImageRGBA gradient() {
  ImageRGBA img(61, 37);
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      float* p = img.at(x, y);
      p[0] = 0.013f * x + 0.0001f * y;
      p[1] = 4.0f * std::sin(0.1f * x * y) * std::sin(0.1f * x * y);
      p[2] = 1.0f / (1.0f + x + y);
      p[3] = 1.0f;
    }
  return img;
}

TEST(ExrSettings, LosslessCompressionsGiveTheHalvesBackAndLossyOnesCloseValues) {
  const std::string dir = test::scratch_dir("exr-settings");
  const ImageRGBA img = gradient();
  for (const std::string& compression : exr_compression_names()) {
    const std::string path = dir + "/" + compression + ".exr";
    write_exr_atomic(path, img, {}, {compression, false});
    Imf::InputFile file(path.c_str());
    EXPECT_EQ(file.header().compression() == Imf::PIZ_COMPRESSION, compression == "piz");
    EXPECT_EQ(file.header().channels().findChannel("R")->type, Imf::HALF);
    const ImageRGBA back = read_exr_file(path);
    double worst = 0.0;
    for (size_t i = 0; i < img.pixels.size(); ++i)
      worst = std::max(worst, double(std::fabs(back.pixels[i] - float(half(img.pixels[i])))));
    if (exr_compression_is_lossless(compression))
      EXPECT_EQ(worst, 0.0) << compression;
    else
      EXPECT_LT(worst, 0.1) << compression;  // DWA: lossy, but the same picture
  }
}

TEST(ExrSettings, FloatChannelsKeepEveryBitAndTheHeaderNamesRec709) {
  const std::string dir = test::scratch_dir("exr-float");
  const ImageRGBA img = gradient();
  write_exr_atomic(dir + "/f.exr", img, {}, {"zip", true});
  Imf::InputFile file((dir + "/f.exr").c_str());
  EXPECT_EQ(file.header().channels().findChannel("G")->type, Imf::FLOAT);
  EXPECT_EQ(file.header().compression(), Imf::ZIP_COMPRESSION);
  EXPECT_EQ(read_exr_file(dir + "/f.exr").pixels, img.pixels);
  ASSERT_TRUE(Imf::hasChromaticities(file.header()));
  const Imf::Chromaticities c = Imf::chromaticities(file.header());
  EXPECT_FLOAT_EQ(c.red.x, 0.64f);  // Rec.709 / sRGB primaries
  EXPECT_FLOAT_EQ(c.green.y, 0.60f);
  EXPECT_FLOAT_EQ(c.blue.x, 0.15f);
  EXPECT_FLOAT_EQ(c.white.x, 0.3127f);  // D65
  EXPECT_THROW(exr_compression_is_lossless("b44"), std::runtime_error);
}

}  // namespace
}  // namespace sdfreel
