// The shipped views in sdfreel's own math against OpenColorIO, the authority, on whatever OCIO
// version is installed: 16-bit display values may differ by at most kTolerance16 units.
#include "io/shipped_views.h"

#include <OpenColorIO/OpenColorIO.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "io/aces_sdr_video.h"
#include "io/color.h"
#include "io/quantise16.h"

namespace OCIO = OCIO_NAMESPACE;

namespace sdfreel {
namespace {

const char* kAces = "ACES 1.0 - SDR Video";
const char* kRaw = "Un-tone-mapped";

// OCIO's optimised CPU processor approximates log, exp and pow (its "fast" SSE forms) and folds
// the matrices; the ACES view runs three logs and three exps in a row. Measured on OCIO 2.1.2
// (Debian 12) over the samples below: ACES at most 1 unit (mean 0.007), Un-tone-mapped 0 (out of
// 65535). OCIO 2.5 moves values by one unit against 2.1 and 2.4, hence 2.
constexpr int kTolerance16 = 2;

// Linear Rec.709 samples: a grey ramp from 1e-6 to 1e4 and an RGB lattice that spans black,
// the shadows, mid grey, white and strong highlights, saturated primaries and a few small
// negative values (which a user's linear shader output may hold).
std::vector<float> samples() {
  std::vector<float> out;
  for (int i = 0; i <= 400; ++i) {
    const float v = std::pow(10.0f, -6.0f + 10.0f * float(i) / 400.0f);
    out.insert(out.end(), {v, v, v, 1.0f});
  }
  const float levels[] = {-0.01f, 0.0f, 1e-4f, 0.002f, 0.02f, 0.08f, 0.18f,
                          0.4f,   1.0f, 2.5f,  8.0f,   40.0f, 300.0f};
  for (float r : levels)
    for (float g : levels)
      for (float b : levels) out.insert(out.end(), {r, g, b, 1.0f});
  return out;
}

std::vector<float> through_ocio(const char* view, std::vector<float> rgba) {
  const std::string path = builtin_ocio_config_path();
  OCIO::ConstConfigRcPtr cfg = OCIO::Config::CreateFromFile(path.c_str());
  OCIO::DisplayViewTransformRcPtr dvt = OCIO::DisplayViewTransform::Create();
  dvt->setSrc(OCIO::ROLE_SCENE_LINEAR);
  dvt->setDisplay("sRGB");
  dvt->setView(view);
  auto cpu = cfg->getProcessor(dvt)->getOptimizedCPUProcessor(
      OCIO::BIT_DEPTH_F32, OCIO::BIT_DEPTH_F32, OCIO::OPTIMIZATION_DEFAULT);
  OCIO::PackedImageDesc desc(rgba.data(), long(rgba.size() / 4), 1, 4);
  cpu->apply(desc);
  return rgba;
}

struct Agreement {
  int max_units = 0;
  double mean_units = 0;
};

Agreement agreement(const char* view) {
  const std::vector<float> in = samples();
  const std::vector<float> ocio = through_ocio(view, in);
  const ShippedView mine = shipped_view("sRGB", view);
  Agreement a;
  for (size_t i = 0; i < in.size(); i += 4) {
    const glm::vec3 out = mine({in[i], in[i + 1], in[i + 2]});
    for (int c = 0; c < 3; ++c) {
      const int d = std::abs(int(quantise16(out[c])) - int(quantise16(ocio[i + c])));
      EXPECT_LE(d, kTolerance16) << view << " channel " << c << " of (" << in[i] << ", "
                                 << in[i + 1] << ", " << in[i + 2] << "): " << out[c] << " here, "
                                 << ocio[i + c] << " by OpenColorIO";
      a.max_units = std::max(a.max_units, d);
      a.mean_units += d;
    }
  }
  a.mean_units /= double(in.size() / 4 * 3);
  return a;
}

TEST(ShippedViews, AcesSdrVideoAgreesWithOpenColorIO) {
  const Agreement a = agreement(kAces);
  std::printf("ACES 1.0 - SDR Video vs OpenColorIO %s: max %d, mean %.3f units of 65535\n",
              OCIO::GetVersion(), a.max_units, a.mean_units);
}

TEST(ShippedViews, UntonemappedAgreesWithOpenColorIO) {
  const Agreement a = agreement(kRaw);
  std::printf("Un-tone-mapped vs OpenColorIO %s: max %d, mean %.3f units of 65535\n",
              OCIO::GetVersion(), a.max_units, a.mean_units);
}

TEST(ShippedViews, OnlyTheShippedDisplayAndViewsHaveOwnMath) {
  EXPECT_NE(shipped_view("sRGB", kAces), nullptr);
  EXPECT_NE(shipped_view("sRGB", kRaw), nullptr);
  EXPECT_EQ(shipped_view("sRGB", "Filmic"), nullptr);
  EXPECT_EQ(shipped_view("P3", kAces), nullptr);
}

// A render of the shipped views does not parse the config (io/color.cpp): every view with its own
// math must be one the shipped file names.
TEST(ShippedViews, EveryViewWithOwnMathIsOneTheShippedConfigNames) {
  const std::vector<std::string> displays = ocio_displays("builtin");
  ASSERT_NE(std::find(displays.begin(), displays.end(), "sRGB"), displays.end());
  const std::vector<std::string> views = ocio_views("builtin", "sRGB");
  for (const char* view : {kAces, kRaw})
    EXPECT_NE(std::find(views.begin(), views.end(), view), views.end()) << view;
}

// The CTL's anchor points: 18% grey maps to 4.8 nits of 48 through the RRT and the ODT, the
// ends of each spline hold flat (RRT) or follow their stated slopes.
TEST(ShippedViews, ToneCurvesHitTheCtlAnchors) {
  const float log_grey = std::log10(0.18f);
  EXPECT_NEAR(rrt_tone_curve_log10(log_grey), std::log10(4.8f), 1e-4f);
  EXPECT_NEAR(odt_48_nits_log10(rrt_tone_curve_log10(log_grey)), std::log10(4.8f), 1e-4f);
  EXPECT_FLOAT_EQ(rrt_tone_curve_log10(-30.0f), -4.0f);
  EXPECT_FLOAT_EQ(rrt_tone_curve_log10(30.0f), 4.0f);
  EXPECT_NEAR(odt_48_nits_log10(-30.0f), std::log10(0.02f), 1e-6f);
}

TEST(ShippedViews, MoncurveMeetsItsLinearSegment) {
  const float at_break = 0.0030399346f;
  EXPECT_NEAR(srgb_encode_moncurve(std::nextafter(at_break, 1.0f)), srgb_encode_moncurve(at_break),
              1e-6f);
  EXPECT_NEAR(srgb_encode_moncurve(1.0f), 1.0f, 1e-6f);
  EXPECT_NEAR(srgb_encode_moncurve(0.18f), 0.4614f, 1e-3f);
}

}  // namespace
}  // namespace sdfreel
