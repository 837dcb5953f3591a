#include "io/shipped_views.h"

#include "io/aces_sdr_video.h"
#include "io/color_matrices.h"
#include "sdf/det_math.h"

namespace sdfreel {
namespace {

// The config's scene_linear space to its reference: the inverse of
// "UTILITY - ACES-AP1_to_LINEAR-REC709_BFD", then "ACEScg_to_ACES2065-1".
Mat3 rec709_to_ap0() {
  return rgb_to_rgb(kAcesAp1, kAcesAp0, false) * inverse(rgb_to_rgb(kAcesAp1, kRec709, true));
}

const Mat3 kXyzD65ToRec709 = inverse(rgb_to_xyz(kRec709));
const FloatMat3 kRec709ToAp0{rec709_to_ap0()};
const FloatMat3 kXyzToDisplay{kXyzD65ToRec709};
// Un-tone-mapped: "UTILITY - ACES-AP0_to_CIE-XYZ-D65_BFD" then the display's matrix, as one.
const FloatMat3 kUntonemapped{kXyzD65ToRec709 * bradford(kAcesAp0.white, kRec709.white) *
                              rgb_to_xyz(kAcesAp0) * rec709_to_ap0()};

glm::vec3 encode(const glm::vec3& c) {
  return {srgb_encode_moncurve(c.r), srgb_encode_moncurve(c.g), srgb_encode_moncurve(c.b)};
}

}  // namespace

float srgb_encode_moncurve(float v) {
  // break = (o g / ((g - 1)(1 + o)))^g, slope = ((g - 1) / o)^(g - 1) ((1 + o) / g)^g.
  constexpr float kBreak = 0.0030399346397784323f, kSlope = 12.923210180787857f;
  if (v <= kBreak) return v * kSlope;
  return dm::pow(v, 1.0f / 2.4f) * 1.055f - 0.055f;
}

glm::vec3 aces_sdr_video_view(const glm::vec3& linear_rec709) {
  return encode(kXyzToDisplay(aces_sdr_video_to_xyz(kRec709ToAp0(linear_rec709))));
}

glm::vec3 untonemapped_view(const glm::vec3& linear_rec709) {
  return encode(kUntonemapped(linear_rec709));
}

ShippedView shipped_view(const std::string& display, const std::string& view) {
  if (display != "sRGB") return nullptr;
  if (view == "ACES 1.0 - SDR Video") return aces_sdr_video_view;
  if (view == "Un-tone-mapped") return untonemapped_view;
  return nullptr;
}

}  // namespace sdfreel
