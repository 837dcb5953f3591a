// The hard cases (tests/hard_cases/<scene>/*.toml): timelines aimed at one known failure each of
// ray marching (grazing rays, eyes inside or under surfaces, huge TIME, far-away cameras, extreme
// fields of view and sizes, degenerate camera paths and operators). Each is rendered at its
// preset (final, 2 samples) on the CPU backend and must give finite pixels, no ray that ran out
// of steps, and an error against its own reference (the reference preset at the same samples,
// so that only the march differs) within the preset's budget.
//
// Each case's guard in the code (a comment there names the case):
//   horizon_grazing        marchWater: leaves once the gap can no longer close (lantern)
//   just_above_water,      marchWater: an eye at or below the crests marches from t = 0
//     under_water
//   inside_lantern         sphereTrace: d < 0 at the start is a hit at once
//   inside_object          sdf_morph march: the same
//   look_straight_up/down  make_camera_basis: +Z as the reference up (render/camera.cpp)
//   time_1e6, time_1e9     make_lake_frame: wave phases wrapped in double (lantern_festival/lake)
//   far_camera_lake        boundInterval: the circle test from the closest approach
//   far_camera_object      intersectSphere: r^2 - |q|^2 instead of b^2 - c (sdf_morph/render)
//   fov_narrow, fov_wide,  footprint_angle: epsilons in pixel footprints, the footprint capped at
//     resolution_1x1,      MAX_FOOTPRINT_ANGLE (render/quality.h); before the cap fov_wide
//     resolution_3x5       failed (26 dB against its reference) and resolution_1x1 had 31.5 dB
//   repeated_camera_keys   centripetal Catmull-Rom: zero knot intervals (timeline/curve.cpp)
//   smooth_union_k0        opSmoothUnion: k <= 0 is the plain union (sdf/sdf.h)
//   flicker_zero           candleStrength: blends, never divides by the strength
//   ray_along_lantern_axis boundInterval: a vertical ray is inside or outside as a whole
//   cell_centre_rays       neighbourSign: sign(0) = +1 (lantern_festival/grid.h)
//   crease_normals         safe_normalize: a tetrahedron normal whose taps cancel (sdf/sdf.h)
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>

#include "backends/cpu/cpu_backend.h"
#include "bench/metrics.h"
#include "pipeline/frame_pipeline.h"
#include "scenes/registry.h"
#include "sdf/sdf.h"
#include "timeline/timeline.h"

namespace sdfreel {
namespace {

namespace fs = std::filesystem;

// The budget of the final preset against the reference at equal samples (display values).
constexpr double FINAL_MIN_PSNR_DB = 30.0;
constexpr double FINAL_MAX_P99_ABS_ERROR = 0.1;
// At least this many cases (the list).
constexpr size_t MIN_CASES = 20;
// TIME = 1e6 / 1e9 must move between frames like TIME = 10: the mean frame-to-frame change may
// differ by the content of the picture, not by orders of magnitude (a float TIME gives 0 or
// jumps of 1/16 s and 64 s there).
constexpr double SMOOTHNESS_MAX_RATIO = 3.0;

std::string case_dir() {
  return std::string(SDFREEL_SOURCE_DIR) + "/tests/hard_cases";
}

// "<scene>/<case>" for every tests/hard_cases/<scene>/<case>.toml.
std::vector<std::string> case_names() {
  std::vector<std::string> names;
  for (const auto& scene : fs::directory_iterator(case_dir())) {
    if (!scene.is_directory()) continue;
    for (const auto& e : fs::directory_iterator(scene.path()))
      if (e.path().extension() == ".toml")
        names.push_back(scene.path().filename().string() + "/" + e.path().stem().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

struct CaseRender {
  Timeline tl;
  std::vector<ImageRGB16> display;
  std::vector<ImageRGBA> linear;
  RayStats stats;
  bench::ErrorMetrics error;  // against the reference preset at the same samples
};

FrameContext context_at(const Timeline& tl, const SceneInfo& scene, int frame, Quality q) {
  FrameContext ctx = frame_context(tl, scene, frame);
  ctx.quality = q;
  finish_frame_context(ctx);
  return ctx;
}

bool all_finite(const ImageRGBA& img) {
  return std::all_of(img.pixels.begin(), img.pixels.end(),
                     [](float v) { return std::isfinite(v); });
}

// Rendered once per case and kept: the smoothness test reuses the TIME cases.
const CaseRender& render_case(const std::string& name) {
  static std::map<std::string, CaseRender> cache;
  auto it = cache.find(name);
  if (it != cache.end()) return it->second;
  CaseRender r;
  r.tl = load_timeline(all_scenes(), case_dir() + "/" + name + ".toml", nullptr);
  FramePipeline pipe(r.tl, std::make_unique<CpuBackend>(0));
  bench::ErrorAccumulator error;
  for (int i = 0; i < r.tl.frame_count(); ++i) {
    // render_context throws on NaN or Inf: that fails the test with the frame and pixel named.
    const RenderedFrame f = pipe.render_context(context_at(r.tl, pipe.scene(), i, r.tl.quality));
    const RenderedFrame ref =
        pipe.render_context(context_at(r.tl, pipe.scene(), i, Quality::Reference));
    error.add(f.display, ref.display);
    r.stats.add(f.stats);
    r.display.push_back(f.display);
    r.linear.push_back(f.linear);
  }
  r.error = error.result();
  return cache.emplace(name, std::move(r)).first->second;
}

class HardCase : public testing::TestWithParam<std::string> {};

TEST_P(HardCase, FiniteUncappedAndWithinBudget) {
  const std::string name = GetParam();
  const CaseRender& r = render_case(name);
  ASSERT_GT(r.linear.size(), 0u);
  EXPECT_EQ(r.tl.scene + "/", name.substr(0, r.tl.scene.size() + 1)) << "in another scene's folder";
  for (const ImageRGBA& img : r.linear) EXPECT_TRUE(all_finite(img)) << name;
  EXPECT_EQ(r.stats.capped, 0u) << name << ": rays ran out of steps";
  EXPECT_GE(r.error.psnr_db, FINAL_MIN_PSNR_DB) << name;
  EXPECT_LE(r.error.p99_abs_error, FINAL_MAX_P99_ABS_ERROR) << name;
  std::printf(
      "[ hard case ] %-24s PSNR %6.2f dB  p99 %.4f  SDF evals/px %.1f\n", name.c_str(),
      r.error.psnr_db, r.error.p99_abs_error,
      double(r.stats.sdf_evals) / (double(r.tl.width) * r.tl.height * double(r.linear.size())));
}

INSTANTIATE_TEST_SUITE_P(Timelines, HardCase, testing::ValuesIn(case_names()),
                         [](const testing::TestParamInfo<std::string>& info) {
                           std::string name = info.param;
                           std::replace(name.begin(), name.end(), '/', '_');
                           return name;
                         });

TEST(HardCases, SuiteIsComplete) {
  const std::vector<std::string> names = case_names();
  EXPECT_GE(names.size(), MIN_CASES);
  // Every case says which failure it aims at.
  for (const std::string& n : names) {
    std::ifstream f(case_dir() + "/" + n + ".toml");
    std::string first;
    std::getline(f, first);
    EXPECT_EQ(first.rfind("# Hard case: ", 0), 0u) << n;
  }
}

// Mean |difference| of display values between consecutive frames.
std::vector<double> frame_steps(const CaseRender& r) {
  std::vector<double> steps;
  for (size_t i = 1; i < r.display.size(); ++i) {
    double sum = 0.0;
    const auto& a = r.display[i - 1].pixels;
    const auto& b = r.display[i].pixels;
    for (size_t k = 0; k < a.size(); ++k) sum += std::abs(double(a[k]) - double(b[k]));
    steps.push_back(sum / double(a.size()) / 65535.0);
  }
  return steps;
}

TEST(HardCases, HugeTimeMovesAsSmoothlyAsSmallTime) {
  const std::vector<double> base = frame_steps(render_case("lantern_festival/time_10"));
  ASSERT_GE(base.size(), 2u);
  double base_mean = 0.0;
  for (double s : base) base_mean += s / double(base.size());
  ASSERT_GT(base_mean, 0.0) << "the TIME = 10 case shows no motion: it tests nothing";
  for (const char* name : {"lantern_festival/time_1e6", "lantern_festival/time_1e9"}) {
    const std::vector<double> steps = frame_steps(render_case(name));
    ASSERT_EQ(steps.size(), base.size());
    for (double s : steps) {
      EXPECT_GT(s, base_mean / SMOOTHNESS_MAX_RATIO) << name << ": frames barely move";
      EXPECT_LT(s, base_mean * SMOOTHNESS_MAX_RATIO) << name << ": frames jump";
    }
  }
}

// The smooth_union_k0 case renders the handle's smooth union; the operator itself with k = 0 (and
// a denormal k) must be the plain union, not 0/0.
TEST(HardCases, SmoothUnionWithZeroK) {
  for (float k : {0.0f, -0.0f, 1e-42f, -1.0f}) {
    EXPECT_EQ(opSmoothUnion(0.3f, -0.2f, k), -0.2f) << k;
    EXPECT_EQ(opSmoothUnion(-0.2f, 0.3f, k), -0.2f) << k;
    EXPECT_EQ(opSmoothUnion(0.5f, 0.5f, k), 0.5f) << k;
  }
  // Continuous as k shrinks to 0: the blend never goes below min - k/4.
  for (float k : {1e-3f, 1e-6f, 1e-12f})
    EXPECT_NEAR(opSmoothUnion(0.5f, 0.5f, k), 0.5f, double(k)) << k;
}

}  // namespace
}  // namespace sdfreel
