#include "io/shipped_views.h"

#include "io/aces_sdr_video.h"
#include "io/color_matrices.h"
#include "sdf/det_math.h"
#include "sdf/lanes_exp_log.h"

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

// One pixel (float channels) or eight (F8 channels): both sides of the branch and a select.
template <class T>
T moncurve(T v) {
  // break = (o g / ((g - 1)(1 + o)))^g, slope = ((g - 1) / o)^(g - 1) ((1 + o) / g)^g.
  constexpr float kBreak = 0.0030399346397784323f, kSlope = 12.923210180787857f;
  return select(v <= kBreak, v * kSlope, dm::pow(v, 1.0f / 2.4f) * 1.055f - 0.055f);
}

template <class V>
V encode(const V& c) {
  return {moncurve(c.x), moncurve(c.y), moncurve(c.z)};
}

template <class V>
V aces_view(const V& linear_rec709) {
  return encode(kXyzToDisplay(aces_sdr_video_to_xyz(kRec709ToAp0(linear_rec709))));
}

template <class V>
V untonemapped(const V& linear_rec709) {
  return encode(kUntonemapped(linear_rec709));
}

// RGBA pixels through a view: whole groups of eight in lanes, the rest one by one.
template <glm::vec3 (*One)(const glm::vec3&), V3x8 (*Eight)(const V3x8&)>
void view_pixels(float* rgba, size_t n) {
  size_t i = 0;
  for (; i + LANES <= n; i += LANES) {
    float* p = rgba + i * 4;
    float r[LANES], g[LANES], b[LANES];
    for (int k = 0; k < LANES; ++k) r[k] = p[k * 4], g[k] = p[k * 4 + 1], b[k] = p[k * 4 + 2];
    const V3x8 out = Eight(V3x8(load8(r), load8(g), load8(b)));
    for (int k = 0; k < LANES; ++k)
      p[k * 4] = out.x[k], p[k * 4 + 1] = out.y[k], p[k * 4 + 2] = out.z[k];
  }
  for (; i < n; ++i) {
    float* p = rgba + i * 4;
    const glm::vec3 out = One({p[0], p[1], p[2]});
    p[0] = out.r, p[1] = out.g, p[2] = out.b;
  }
}

}  // namespace

float srgb_encode_moncurve(float v) {
  return moncurve(v);
}

glm::vec3 aces_sdr_video_view(const glm::vec3& linear_rec709) {
  return aces_view(linear_rec709);
}

glm::vec3 untonemapped_view(const glm::vec3& linear_rec709) {
  return untonemapped(linear_rec709);
}

ShippedView shipped_view(const std::string& display, const std::string& view) {
  if (display != "sRGB") return nullptr;
  if (view == "ACES 1.0 - SDR Video") return aces_sdr_video_view;
  if (view == "Un-tone-mapped") return untonemapped_view;
  return nullptr;
}

ShippedViewPixels shipped_view_pixels(const std::string& display, const std::string& view) {
  const ShippedView one = shipped_view(display, view);
  if (one == aces_sdr_video_view) return view_pixels<aces_view, aces_view>;
  if (one == untonemapped_view) return view_pixels<untonemapped, untonemapped>;
  return nullptr;
}

}  // namespace sdfreel
