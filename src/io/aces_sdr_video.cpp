#include "io/aces_sdr_video.h"

#include <algorithm>

#include "io/color_matrices.h"
#include "sdf/det_math.h"
#include "sdf/lanes_exp_log.h"

namespace sdfreel {
namespace {

constexpr float kLog10Of2 = 0.301029996f;
constexpr float kLog10OfMid = -0.744727495f;  // log10(0.18)
constexpr float kLn10 = 2.30258509f;

// Every step is a template on the pixel type: glm::vec3 (one pixel, channels float) or V3x8
// (eight pixels, channels F8). A branch is both sides and a select, so each lane has the bits of
// the single pixel.
template <class T>
T uniform(float v);
template <>
float uniform<float>(float v) {
  return v;
}
template <>
F8 uniform<F8>(float v) {
  return splat(v);
}

template <class T>
T log10f_det(T x) {
  return dm::log(x) * (1.0f / kLn10);
}
template <class T>
T pow10f_det(T x) {
  return dm::exp(x * kLn10);
}

// A segmented quadratic B-spline in log-log space (ACESlib.Tonescales.ctl): N knots between
// min and mid, N between mid and max, straight lines outside. Each segment's quadratic (the CTL's
// basis matrix times its three coefficients) is worked out once, in the same float operations.
template <int N>
class SegmentedSpline {
 public:
  SegmentedSpline(const float (&coefs_low)[N + 2], const float (&coefs_high)[N + 2],
                  float log_min_x, float log_min_y, float log_mid_x, float log_max_x,
                  float log_max_y, float slope_low, float slope_high)
      : log_min_x_(log_min_x),
        log_min_y_(log_min_y),
        log_mid_x_(log_mid_x),
        log_max_x_(log_max_x),
        log_max_y_(log_max_y),
        slope_low_(slope_low),
        slope_high_(slope_high) {
    for (int j = 0; j < N; ++j) {
      set_segment(j, coefs_low + j);
      set_segment(N + j, coefs_high + j);
    }
  }

  template <class T>
  T operator()(T log_x) const {
    const auto in_low = log_x < log_mid_x_;
    const T knot_low = float(N - 1) * (log_x - log_min_x_) / (log_mid_x_ - log_min_x_);
    const T knot_high = float(N - 1) * (log_x - log_mid_x_) / (log_max_x_ - log_mid_x_);
    const T knot = select(in_low, knot_low, knot_high);
    // int(knot), at most N - 1; knot >= 0 where the spline is used (0 elsewhere, NaN included).
    const T j = dm::to_float(
        dm::to_int(select(knot > 0.0f, dm::min(knot, float(N - 1)), uniform<T>(0.0f))));
    const auto row = dm::to_int(j + select(in_low, uniform<T>(0.0f), uniform<T>(float(N))));
    const T t = knot - j;
    const T spline = (t * t) * gather(a_, row) + t * gather(b_, row) + gather(c_, row);
    const T below = log_x * slope_low_ + (log_min_y_ - slope_low_ * log_min_x_);
    const T above = log_x * slope_high_ + (log_max_y_ - slope_high_ * log_max_x_);
    return select(log_x <= log_min_x_, below, select(log_x < log_max_x_, spline, above));
  }

 private:
  void set_segment(int row, const float* cf) {
    const float c0 = cf[0], c1 = cf[1], c2 = cf[2];
    a_[row] = 0.5f * c0 - c1 + 0.5f * c2;
    b_[row] = c1 - c0;
    c_[row] = 0.5f * c0 + 0.5f * c1;
  }

  float a_[2 * N], b_[2 * N], c_[2 * N];  // rows 0..N-1 below mid, N..2N-1 above
  float log_min_x_, log_min_y_, log_mid_x_, log_max_x_, log_max_y_;
  float slope_low_, slope_high_;
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

template <class V>
auto saturation(const V& c) {
  const auto lo = dm::min(c.x, dm::min(c.y, c.z)), hi = dm::max(c.x, dm::max(c.y, c.z));
  return (dm::max(1e-10f, hi) - dm::max(1e-10f, lo)) / dm::max(1e-2f, hi);
}

template <class V>
V glow(const V& c) {
  using T = decltype(c.x);
  constexpr float kGain = 0.05f, kMid = 0.08f;
  const T chroma = dm::sqrt(c.z * (c.z - c.y) + c.y * (c.y - c.x) + c.x * (c.x - c.z));
  const T yc = (c.z + c.y + c.x + 1.75f * chroma) / 3.0f;
  const T x = (saturation(c) - 0.4f) * 5.0f;  // sigmoid shaper of the saturation
  const T sign = select(x < 0.0f, uniform<T>(-1.0f), uniform<T>(1.0f));
  const T t = dm::max(0.0f, 1.0f - 0.5f * sign * x);
  const T gain = kGain * ((1.0f + sign * (1.0f - t * t)) * 0.5f);
  const T added = select(yc >= kMid * 2.0f, uniform<T>(0.0f),
                         select(yc <= kMid * 2.0f / 3.0f, gain, gain * (kMid / yc - 0.5f)));
  return c * (1.0f + added);
}

// Quadratic B-spline weight of the hue around red, 135 degrees wide.
template <class V>
auto red_hue_weight(const V& c) {
  using T = decltype(c.x);
  // kM[i][j]: coefficient i (of t^3 .. 1) of segment j.
  static constexpr float kM[4][4] = {{0.25f, -0.75f, 0.75f, -0.25f},
                                     {0.00f, 0.75f, -1.50f, 0.75f},
                                     {0.00f, 0.75f, 0.00f, -0.75f},
                                     {0.00f, 0.25f, 1.00f, 0.25f}};
  const T a = 2.0f * c.x - (c.y + c.z);
  const T b = 1.7320508075688772f * (c.y - c.z);
  const T knot = dm::atan2(b, a) * 1.6976527263135504f + 2.0f;
  const auto inside = (knot > -1.0f) & (knot < 4.0f);  // int(knot) in 0..3; NaN outside
  const auto j = dm::to_int(select(inside, knot, uniform<T>(0.0f)));
  const T t = knot - dm::to_float(j);
  const T w =
      gather(kM[3], j) + t * (gather(kM[2], j) + t * (gather(kM[1], j) + t * gather(kM[0], j)));
  return select(inside, w, uniform<T>(0.0f));
}

template <class V>
V red_modifier(V c) {
  const auto hue = red_hue_weight(c);
  c.x = select(hue > 0.0f, c.x + hue * saturation(c) * (0.03f - c.x) * (1.0f - 0.82f), c.x);
  return c;
}

template <class V>
V at_least_zero(const V& c) {
  return {dm::max(0.0f, c.x), dm::max(0.0f, c.y), dm::max(0.0f, c.z)};
}

const FloatMat3 kAp0ToAp1{rgb_to_rgb(kAcesAp0, kAcesAp1, false)};
const FloatMat3 kRrtSaturation{Mat3{{{0.970889148671, 0.026963270632, 0.002147580696},
                                     {0.010889148671, 0.986963270632, 0.002147580696},
                                     {0.010889148671, 0.026963270632, 0.962147580696}}}};
const FloatMat3 kDesat100Nits{Mat3{{{0.949056010175, 0.047185723607, 0.003758266219},
                                    {0.019056010175, 0.977185723607, 0.003758266219},
                                    {0.019056010175, 0.047185723607, 0.933758266219}}}};
const FloatMat3 kAp1ToXyzD65{bradford(kAcesAp1.white, kRec709.white) * rgb_to_xyz(kAcesAp1)};

template <class T>
T tone_curve(T v) {
  const T log_y = kOdt48(kRrt(log10f_det(dm::max(v, 1.17549435e-38f))));
  // Cinema white and black: 48 nits -> 1, 0.02 nits -> 0.
  return (pow10f_det(log_y) - 0.02f) * (1.0f / (48.0f - 0.02f));
}

// Cinema (dark surround) to video (dim surround): luminance to the power 0.9811.
template <class V>
V dark_to_dim(const V& c) {
  const auto y = dm::max(1e-10f, 0.27222871678091454f * c.x + 0.67408176581114831f * c.y +
                                     0.053689517407937051f * c.z);
  return c * dm::pow(y, 0.9811f - 1.0f);
}

template <class V>
V to_xyz(const V& aces2065) {
  V c = at_least_zero(red_modifier(glow(aces2065)));
  c = kRrtSaturation(at_least_zero(kAp0ToAp1(c)));
  c = {tone_curve(c.x), tone_curve(c.y), tone_curve(c.z)};
  return kAp1ToXyzD65(kDesat100Nits(dark_to_dim(c)));
}

}  // namespace

float rrt_tone_curve_log10(float log_x) {
  return kRrt(log_x);
}
float odt_48_nits_log10(float log_x) {
  return kOdt48(log_x);
}

glm::vec3 aces_sdr_video_to_xyz(const glm::vec3& aces2065) {
  return to_xyz(aces2065);
}
V3x8 aces_sdr_video_to_xyz(const V3x8& aces2065) {
  return to_xyz(aces2065);
}

}  // namespace sdfreel
