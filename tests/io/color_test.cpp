// The shipped OCIO config and the scene-linear -> display transform.
#include "io/color.h"

#include <OpenColorIO/OpenColorIO.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <stdexcept>
#include <thread>

#include "io/quantise16.h"
#include "io/shipped_views.h"

namespace OCIO = OCIO_NAMESPACE;

namespace sdfreel {
namespace {

const char* kDisplay = "sRGB";
const char* kAces = "ACES 1.0 - SDR Video";
const char* kRaw = "Un-tone-mapped";

// A grey ramp, one pixel per value, alpha 1.
ImageRGBA grey_ramp(const std::vector<float>& values) {
  ImageRGBA img(int(values.size()), 1);
  for (size_t i = 0; i < values.size(); ++i) {
    float* p = img.at(int(i), 0);
    p[0] = p[1] = p[2] = values[i];
    p[3] = 1.0f;
  }
  return img;
}

// The sRGB encoding (IEC 61966-2-1), written independently of OCIO.
double srgb_encode(double v) {
  return v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055;
}

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

TEST(OcioConfig, ShippedConfigIsFoundAndValid) {
  const std::string path = builtin_ocio_config_path();
  ASSERT_TRUE(std::filesystem::is_regular_file(path)) << path;
  OCIO::ConstConfigRcPtr cfg = OCIO::Config::CreateFromFile(path.c_str());
  EXPECT_NO_THROW(cfg->validate());
  EXPECT_STREQ(cfg->getColorSpace(OCIO::ROLE_SCENE_LINEAR)->getName(), "Linear Rec.709 (sRGB)");
  for (const char* name : {"ACEScg", "ACES2065-1", "Raw", "sRGB - Display"})
    EXPECT_NE(cfg->getColorSpace(name), nullptr) << name;
}

TEST(OcioConfig, ListsDisplaysAndViews) {
  EXPECT_EQ(ocio_displays("builtin"), std::vector<std::string>{kDisplay});
  const auto views = ocio_views("builtin", kDisplay);
  EXPECT_NE(std::find(views.begin(), views.end(), kAces), views.end());
  EXPECT_NE(std::find(views.begin(), views.end(), kRaw), views.end());
  EXPECT_TRUE(ocio_views("builtin", "no such display").empty());
}

TEST(OcioConfig, EnvironmentVariableOverridesTheShippedPath) {
  const std::string shipped = builtin_ocio_config_path();
  setenv("SDFREEL_OCIO_CONFIG", "/nonexistent/elsewhere.ocio", 1);
  const std::string overridden = builtin_ocio_config_path();
  unsetenv("SDFREEL_OCIO_CONFIG");
  EXPECT_EQ(overridden, "/nonexistent/elsewhere.ocio");
  EXPECT_EQ(builtin_ocio_config_path(), shipped);
}

TEST(OcioConfig, ConfigByPathAndByOcioVariable) {
  const std::string path = builtin_ocio_config_path();
  EXPECT_NO_THROW(DisplayTransform(path, kDisplay, kAces));
  setenv("OCIO", path.c_str(), 1);
  EXPECT_NO_THROW(DisplayTransform("env", kDisplay, kAces));
  EXPECT_NO_THROW(DisplayTransform("$OCIO", kDisplay, kAces));
  unsetenv("OCIO");
  EXPECT_NE(error_of([] { DisplayTransform("env", kDisplay, kAces); }).find("not set"),
            std::string::npos);
}

TEST(DisplayTransformErrors, NameWhatExists) {
  const std::string bad_display = error_of([] { DisplayTransform("builtin", "P3", kAces); });
  EXPECT_NE(bad_display.find("\"P3\""), std::string::npos) << bad_display;
  EXPECT_NE(bad_display.find("\"sRGB\""), std::string::npos) << bad_display;

  const std::string bad_view = error_of([] { DisplayTransform("builtin", kDisplay, "Filmic"); });
  EXPECT_NE(bad_view.find("\"Filmic\""), std::string::npos) << bad_view;
  EXPECT_NE(bad_view.find(kAces), std::string::npos) << bad_view;
  EXPECT_NE(bad_view.find(kRaw), std::string::npos) << bad_view;

  const std::string missing =
      error_of([] { DisplayTransform("/nonexistent/config.ocio", kDisplay, kAces); });
  EXPECT_NE(missing.find("not found"), std::string::npos) << missing;
}

TEST(DisplayTransformErrors, BrokenConfigIsReported) {
  const auto path = std::filesystem::temp_directory_path() /
                    ("sdfreel-broken-" + std::to_string(::getpid()) + ".ocio");
  { std::ofstream(path) << "ocio_profile_version: 2\nroles: [this is not a map\n"; }
  const std::string msg = error_of([&] { DisplayTransform(path.string(), kDisplay, kAces); });
  std::filesystem::remove(path);
  EXPECT_NE(msg.find("invalid"), std::string::npos) << msg;
}

TEST(DisplayTransform, DescriptionNamesConfigDisplayAndView) {
  EXPECT_EQ(DisplayTransform("builtin", kDisplay, kAces).description(),
            std::string("builtin / sRGB / ") + kAces);
}

TEST(DisplayTransform, UntonemappedIsTheSrgbEncoding) {
  const std::vector<float> values = {0.0f, 0.001f, 0.01f, 0.18f, 0.5f, 1.0f};
  const ImageRGB16 out = DisplayTransform("builtin", kDisplay, kRaw).apply(grey_ramp(values));
  for (size_t i = 0; i < values.size(); ++i) {
    const double expected = srgb_encode(values[i]) * 65535.0;
    for (int c = 0; c < 3; ++c)  // OCIO folds the AP1/AP0/XYZ matrices back to identity
      EXPECT_NEAR(out.pixels[i * 3 + c], expected, 1.0) << values[i];
  }
  EXPECT_EQ(out.pixels[0], 0);
}

TEST(DisplayTransform, BothViewsMapBlackToZeroAndRiseMonotonically) {
  std::vector<float> values;
  for (int i = 0; i <= 200; ++i) values.push_back(std::ldexp(float(i), -5));  // 0 .. 6.25
  const ImageRGBA ramp = grey_ramp(values);
  for (const char* view : {kAces, kRaw}) {
    const ImageRGB16 out = DisplayTransform("builtin", kDisplay, view).apply(ramp);
    EXPECT_EQ(out.pixels[0], 0) << view;
    EXPECT_EQ(out.pixels[1], 0) << view;
    EXPECT_EQ(out.pixels[2], 0) << view;
    for (size_t i = 1; i < values.size(); ++i)
      for (int c = 0; c < 3; ++c)
        EXPECT_GE(out.pixels[i * 3 + c], out.pixels[(i - 1) * 3 + c]) << view << " " << values[i];
    // A neutral input stays neutral on the display.
    for (size_t i = 0; i < values.size(); ++i) {
      EXPECT_NEAR(out.pixels[i * 3 + 0], out.pixels[i * 3 + 1], 2) << view << " " << values[i];
      EXPECT_NEAR(out.pixels[i * 3 + 2], out.pixels[i * 3 + 1], 2) << view << " " << values[i];
    }
  }
}

TEST(DisplayTransform, AcesViewToneMapsWhatTheOtherClips) {
  const ImageRGBA img = grey_ramp({0.18f, 4.0f, -1.0f});
  const ImageRGB16 aces = DisplayTransform("builtin", kDisplay, kAces).apply(img);
  const ImageRGB16 raw = DisplayTransform("builtin", kDisplay, kRaw).apply(img);
  EXPECT_NE(aces.pixels, raw.pixels);
  EXPECT_EQ(raw.pixels[3], 65535);   // 4.0 clips without a tone curve
  EXPECT_LT(aces.pixels[3], 65535);  // and is still below display white with one
  EXPECT_GT(aces.pixels[3], aces.pixels[0]);
  EXPECT_NE(aces.pixels[0], raw.pixels[0]);
  for (int c = 0; c < 3; ++c) {  // negative light clamps to black
    EXPECT_EQ(aces.pixels[6 + c], 0);
    EXPECT_EQ(raw.pixels[6 + c], 0);
  }
}

TEST(DisplayTransform, ConcurrentCallsGiveTheSameBitsAsOne) {
  ImageRGBA img(61, 101);  // several conversion chunks, odd sizes
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      float* p = img.at(x, y);
      p[0] = float(x) / 20.0f;
      p[1] = float(y) / 9.0f;
      p[2] = float((x * 7 + y * 13) % 17) / 4.0f;
      p[3] = 1.0f;
    }
  const DisplayTransform transform("builtin", kDisplay, kAces);
  const ImageRGB16 reference = transform.apply(img);
  EXPECT_EQ(reference.width, img.width);
  EXPECT_EQ(reference.height, img.height);
  std::vector<ImageRGB16> results(4);
  std::vector<std::thread> threads;
  for (auto& r : results)
    threads.emplace_back([&] {
      for (int k = 0; k < 5; ++k) r = transform.apply(img);
    });
  for (auto& t : threads) t.join();
  for (const auto& r : results) EXPECT_EQ(r.pixels, reference.pixels);
  // A second transform object built from scratch agrees too.
  EXPECT_EQ(DisplayTransform("builtin", kDisplay, kAces).apply(img).pixels, reference.pixels);
  // So does converting the image one row at a time (no dependence on how the work is split).
  for (int y = 0; y < img.height; ++y) {
    ImageRGBA row(img.width, 1);
    std::copy(img.at(0, y), img.at(0, y) + img.width * 4, row.pixels.begin());
    const ImageRGB16 out = transform.apply(row);
    ASSERT_TRUE(std::equal(out.pixels.begin(), out.pixels.end(),
                           reference.pixels.begin() + size_t(y) * img.width * 3))
        << "row " << y;
  }
}

// "builtin" is sdfreel's own math (io/shipped_views.h), the same file by path is OpenColorIO's:
// the builtin pixels are exactly the shipped view's, the path's exactly OCIO's processor's.
TEST(DisplayTransform, BuiltinViewsAreOwnMathAndAConfigByPathIsOpenColorIO) {
  std::vector<float> values;
  for (int i = 0; i <= 64; ++i) values.push_back(std::ldexp(float(i * i), -8));  // 0 .. 16
  const ImageRGBA ramp = grey_ramp(values);
  const std::string path = builtin_ocio_config_path();
  for (const char* view : {kAces, kRaw}) {
    const ImageRGB16 builtin = DisplayTransform("builtin", kDisplay, view).apply(ramp);
    const ShippedView own = shipped_view(kDisplay, view);
    for (size_t i = 0; i < values.size(); ++i)
      EXPECT_EQ(builtin.pixels[i * 3], quantise16(own(glm::vec3(values[i])).r)) << view;

    OCIO::ConstConfigRcPtr cfg = OCIO::Config::CreateFromFile(path.c_str());
    OCIO::DisplayViewTransformRcPtr dvt = OCIO::DisplayViewTransform::Create();
    dvt->setSrc(OCIO::ROLE_SCENE_LINEAR);
    dvt->setDisplay(kDisplay);
    dvt->setView(view);
    std::vector<float> rgba = ramp.pixels;
    OCIO::PackedImageDesc desc(rgba.data(), ramp.width, 1, 4);
    cfg->getProcessor(dvt)
        ->getOptimizedCPUProcessor(OCIO::BIT_DEPTH_F32, OCIO::BIT_DEPTH_F32,
                                   OCIO::OPTIMIZATION_DEFAULT)
        ->apply(desc);
    const ImageRGB16 by_path = DisplayTransform(path, kDisplay, view).apply(ramp);
    for (size_t i = 0; i < values.size(); ++i)
      for (int c = 0; c < 3; ++c)
        EXPECT_EQ(by_path.pixels[i * 3 + c], quantise16(rgba[i * 4 + c])) << view;
  }
}

}  // namespace
}  // namespace sdfreel
