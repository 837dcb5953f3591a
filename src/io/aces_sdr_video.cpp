#include "io/aces_sdr_video.h"

#include <algorithm>

#include "io/color_matrices.h"
#include "sdf/det_math.h"

namespace sdfreel {
namespace {

constexpr float kLog10Of2 = 0.301029996f;
constexpr float kLog10OfMid = -0.744727495f;  // log10(0.18)
constexpr float kLn10 = 2.30258509f;

float log10f_det(float x) {
  return dm::log(x) * (1.0f / kLn10);
}
float pow10f_det(float x) {
  return dm::exp(x * kLn10);
}

// A segmented quadratic B-spline in log-log space (ACESlib.Tonescales.ctl): N knots between
// min and mid, N between mid and max, straight lines outside.
template <int N>
struct SegmentedSpline {
  float coefs_low[N + 2];
  float coefs_high[N + 2];
  float log_min_x, log_min_y, log_mid_x, log_max_x, log_max_y;
  float slope_low, slope_high;

  static float segment(const float* cf, float knot) {
    const int j = std::min(int(knot), N - 1);  // knot >= 0 here; rounding may reach N
    const float t = knot - float(j);
    const float c0 = cf[j], c1 = cf[j + 1], c2 = cf[j + 2];
    // monomials (t^2, t, 1) times cf times the CTL's basis matrix M.
    const float a = 0.5f * c0 - c1 + 0.5f * c2;
    const float b = c1 - c0;
    const float c = 0.5f * c0 + 0.5f * c1;
    return (t * t) * a + t * b + c;
  }

  float operator()(float log_x) const {
    if (log_x <= log_min_x) return log_x * slope_low + (log_min_y - slope_low * log_min_x);
    if (log_x < log_mid_x)
      return segment(coefs_low, float(N - 1) * (log_x - log_min_x) / (log_mid_x - log_min_x));
    if (log_x < log_max_x)
      return segment(coefs_high, float(N - 1) * (log_x - log_mid_x) / (log_max_x - log_mid_x));
    return log_x * slope_high + (log_max_y - slope_high * log_max_x);
  }
};

// RRT_PARAMS: 0.18 * 2^-15 -> 1e-4, 0.18 -> 4.8, 0.18 * 2^18 -> 1e4 (in relative luminance).
const SegmentedSpline<4> kRrt{
    {-4.0000000000f, -4.0000000000f, -3.1573765773f, -0.4852499958f, 1.8477324706f, 1.8477324706f},
    {-0.7185482425f, 2.0810307172f, 3.6681241237f, 4.0000000000f, 4.0000000000f, 4.0000000000f},
    kLog10OfMid - 15.0f * kLog10Of2,
    -4.0f,
    kLog10OfMid,
    kLog10OfMid + 18.0f * kLog10Of2,
    4.0f,
    0.0f,
    0.0f};

// ODT_48nits: its knots are the RRT's outputs for 0.18 * 2^-6.5, 0.18 and 0.18 * 2^6.5 and map
// to 0.02, 4.8 and 48 nits.
const SegmentedSpline<8> kOdt48{
    {-1.6989700043f, -1.6989700043f, -1.4779000000f, -1.2291000000f, -0.8648000000f, -0.4480000000f,
     0.0051800000f, 0.4511080334f, 0.9113744414f, 0.9113744414f},
    {0.5154386965f, 0.8470437783f, 1.1358000000f, 1.3802000000f, 1.5197000000f, 1.5985000000f,
     1.6467000000f, 1.6746091357f, 1.6878733390f, 1.6878733390f},
    kRrt(kLog10OfMid - 6.5f * kLog10Of2),
    -1.69897000f,  // log10(0.02)
    kRrt(kLog10OfMid),
    kRrt(kLog10OfMid + 6.5f * kLog10Of2),
    1.68124124f,  // log10(48)
    0.0f,
    0.04f};

// ---- the RRT's preamble (ACES 1.0 glow and red modifier, OCIO's FixedFunction ops) ----

float saturation(const glm::vec3& c) {
  const float lo = std::min(c.r, std::min(c.g, c.b)), hi = std::max(c.r, std::max(c.g, c.b));
  return (std::max(1e-10f, hi) - std::max(1e-10f, lo)) / std::max(1e-2f, hi);
}

glm::vec3 glow(const glm::vec3& c) {
  constexpr float kGain = 0.05f, kMid = 0.08f;
  const float chroma = dm::sqrt(c.b * (c.b - c.g) + c.g * (c.g - c.r) + c.r * (c.r - c.b));
  const float yc = (c.b + c.g + c.r + 1.75f * chroma) / 3.0f;
  const float x = (saturation(c) - 0.4f) * 5.0f;  // sigmoid shaper of the saturation
  const float sign = x < 0.0f ? -1.0f : 1.0f;
  const float t = std::max(0.0f, 1.0f - 0.5f * sign * x);
  const float gain = kGain * ((1.0f + sign * (1.0f - t * t)) * 0.5f);
  float added;
  if (yc >= kMid * 2.0f)
    added = 0.0f;
  else if (yc <= kMid * 2.0f / 3.0f)
    added = gain;
  else
    added = gain * (kMid / yc - 0.5f);
  return c * (1.0f + added);
}

// Quadratic B-spline weight of the hue around red, 135 degrees wide.
float red_hue_weight(const glm::vec3& c) {
  const float a = 2.0f * c.r - (c.g + c.b);
  const float b = 1.7320508075688772f * (c.g - c.b);
  const float knot = dm::atan2(b, a) * 1.6976527263135504f + 2.0f;
  const int j = int(knot);
  if (j < 0 || j >= 4) return 0.0f;
  static constexpr float kM[4][4] = {{0.25f, 0.00f, 0.00f, 0.00f},
                                     {-0.75f, 0.75f, 0.75f, 0.25f},
                                     {0.75f, -1.50f, 0.00f, 1.00f},
                                     {-0.25f, 0.75f, -0.75f, 0.25f}};
  const float t = knot - float(j);
  const float* k = kM[j];
  return k[3] + t * (k[2] + t * (k[1] + t * k[0]));
}

glm::vec3 red_modifier(glm::vec3 c) {
  const float hue = red_hue_weight(c);
  if (hue > 0.0f) c.r = c.r + hue * saturation(c) * (0.03f - c.r) * (1.0f - 0.82f);
  return c;
}

glm::vec3 at_least_zero(const glm::vec3& c) {
  return {std::max(0.0f, c.r), std::max(0.0f, c.g), std::max(0.0f, c.b)};
}

const FloatMat3 kAp0ToAp1{rgb_to_rgb(kAcesAp0, kAcesAp1, false)};
const FloatMat3 kRrtSaturation{Mat3{{{0.970889148671, 0.026963270632, 0.002147580696},
                                     {0.010889148671, 0.986963270632, 0.002147580696},
                                     {0.010889148671, 0.026963270632, 0.962147580696}}}};
const FloatMat3 kDesat100Nits{Mat3{{{0.949056010175, 0.047185723607, 0.003758266219},
                                    {0.019056010175, 0.977185723607, 0.003758266219},
                                    {0.019056010175, 0.047185723607, 0.933758266219}}}};
const FloatMat3 kAp1ToXyzD65{bradford(kAcesAp1.white, kRec709.white) * rgb_to_xyz(kAcesAp1)};

float tone_curve(float v) {
  const float log_y = kOdt48(kRrt(log10f_det(std::max(v, 1.17549435e-38f))));
  // Cinema white and black: 48 nits -> 1, 0.02 nits -> 0.
  return (pow10f_det(log_y) - 0.02f) * (1.0f / (48.0f - 0.02f));
}

// Cinema (dark surround) to video (dim surround): luminance to the power 0.9811.
glm::vec3 dark_to_dim(const glm::vec3& c) {
  const float y = std::max(1e-10f, 0.27222871678091454f * c.r + 0.67408176581114831f * c.g +
                                       0.053689517407937051f * c.b);
  return c * dm::pow(y, 0.9811f - 1.0f);
}

}  // namespace

float rrt_tone_curve_log10(float log_x) {
  return kRrt(log_x);
}
float odt_48_nits_log10(float log_x) {
  return kOdt48(log_x);
}

glm::vec3 aces_sdr_video_to_xyz(const glm::vec3& aces2065) {
  glm::vec3 c = at_least_zero(red_modifier(glow(aces2065)));
  c = kRrtSaturation(at_least_zero(kAp0ToAp1(c)));
  c = {tone_curve(c.r), tone_curve(c.g), tone_curve(c.b)};
  return kAp1ToXyzD65(kDesat100Nits(dark_to_dim(c)));
}

}  // namespace sdfreel
