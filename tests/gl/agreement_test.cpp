// Every registered scene in process on both backends: the GLSL twin computes the same linear floats
// as the C++ scene, bit for bit, and the same SDF evaluation count, pixel by pixel (the sdf_evals
// compositing pass), for every march preset and mode (draft, final, reference, naive, hit mask),
// with every parameter at its minimum and at its maximum, from the scene's test poses
// (test_camera_poses: the default camera, two views of it any scene gets, SceneInfo::test_poses). A
// mismatch names the first pixels. Scenes whose plan has a mesh pass (museum) are judged by
// Filament's rule instead (gl/filament_rule.h): rasterisers need not agree to the bit; so is every
// scene on a Mesa whose llvmpipe is not bit-exact (gl/mesa_bits.h), where the count of differing
// pixels is printed.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "backends/cpu/cpu_backend.h"
#include "backends/gl/gl_backend.h"
#include "gl/filament_rule.h"
#include "gl/mesa_bits.h"
#include "scenes/registry.h"

namespace sdfreel {
namespace {

constexpr int W = 64, H = 36;
constexpr double TIME = 3.0;

// How a case sets up the frame beyond the scene's defaults.
enum class Mode {
  Draft,
  Final,
  Reference,
  Naive,
  FinalHitMask,
  NaiveHitMask,
  ParamsMin,
  ParamsMax,
  FinalAdaptive  // per-pixel adaptive sampling: the same samples a pixel and the same sums
};

struct Case {
  std::string scene;
  Mode mode;
};

void PrintTo(const Case& c, std::ostream* os) {
  *os << c.scene << ", mode " << int(c.mode);
}

FrameContext context(const SceneInfo& info, Mode mode, const CameraPose& pose) {
  FrameContext ctx;
  ctx.width = W;
  ctx.height = H;
  ctx.samples = 1;
  ctx.scene_time = ctx.video_time = TIME;
  ctx.seed = 1;
  ctx.quality = mode == Mode::Draft       ? Quality::Draft
                : mode == Mode::Reference ? Quality::Reference
                                          : Quality::Final;
  ctx.pose = pose;
  ctx.params = ParamValues(&info.params);
  if (mode == Mode::ParamsMin || mode == Mode::ParamsMax)
    for (const ParamSpec& p : info.params)
      ctx.params.set(p.name, std::vector<double>(size_t(p.components),
                                                 mode == Mode::ParamsMin ? p.min : p.max));
  finish_frame_context(ctx);
  if (mode == Mode::Naive || mode == Mode::NaiveHitMask) ctx.march = naive_march_settings();
  ctx.march.hit_mask = mode == Mode::FinalHitMask || mode == Mode::NaiveHitMask;
  if (mode == Mode::FinalAdaptive) {
    ctx.adaptive = AdaptiveSampling{true, 2, 8, 0.01f};
    finish_frame_context(ctx);
  }
  return ctx;
}

// Does the scene's frame plan draw meshes (so that only Filament's rule applies)?
bool has_mesh_pass(const SceneInfo& info, const FrameContext& ctx) {
  std::unique_ptr<Scene> scene = info.make();
  scene->prepare(ctx);
  for (const Pass& p : scene->frame_plan(ctx).passes)
    if (std::holds_alternative<MeshPass>(p)) return true;
  return false;
}

class Agreement : public ::testing::TestWithParam<Case> {
 protected:
  void SetUp() override {
    info = find_scene(GetParam().scene);
    ASSERT_NE(info, nullptr);
    try {
      osmesa = std::make_unique<GlBackend>();
    } catch (const std::exception& e) {
      GTEST_SKIP() << "OSMesa unavailable: " << e.what();
    }
    osmesa->record_sdf_evals(true);  // the sdf_evals compositing pass, compared pixel by pixel
    cpu.record_sdf_evals(true);
    osmesa->begin(*info);
    cpu.begin(*info);
    bit_exact = test::llvmpipe_bit_exact(*osmesa);
  }

  // Renders ctx on both backends and expects identical floats and SDF evaluation counts; returns
  // the count (a pose that sees nothing may evaluate no SDF at all).
  uint64_t expect_identical(const FrameContext& ctx, const std::string& what) {
    RayStats cpu_stats, gl_stats;
    const ImageRGBA a = cpu.render(ctx, cpu_stats);
    const ImageRGBA b = osmesa->render(ctx, gl_stats);
    EXPECT_EQ(a.pixels.size(), b.pixels.size()) << what;
    if (a.pixels.size() != b.pixels.size()) return 0;
    if (has_mesh_pass(*info, ctx) || !bit_exact) {
      const test::FilamentVerdict v = test::filament_compare(
          a, b, info->name + "-" + std::to_string(int(GetParam().mode)) + "-" + what);
      EXPECT_TRUE(v.pass) << what << ": mean " << v.mean << "/255, share over 5/255 "
                          << v.share_over_5 * 100.0 << "%, images in " << v.images;
      if (!bit_exact) {
        size_t differing = 0;
        for (size_t i = 0; i < a.pixels.size(); i += 4)
          differing += std::memcmp(&a.pixels[i], &b.pixels[i], 4 * sizeof(float)) != 0;
        std::printf("%s: %zu of %zu pixels differ (Mesa %s is not bit-exact; mean %.4f/255)\n",
                    what.c_str(), differing, a.pixels.size() / 4,
                    osmesa->versions()["mesa"].c_str(), v.mean);
      }
      meshes = meshes || has_mesh_pass(*info, ctx);
      return cpu_stats.sdf_evals;
    }
    int differing = 0;
    for (int y = 0; y < H; ++y)
      for (int x = 0; x < W; ++x)
        if (std::memcmp(a.at(x, y), b.at(x, y), 4 * sizeof(float)) != 0 && differing++ < 3)
          ADD_FAILURE() << what << ": pixel (" << x << ", " << y << ") cpu (" << a.at(x, y)[0]
                        << ", " << a.at(x, y)[1] << ", " << a.at(x, y)[2] << "), osmesa ("
                        << b.at(x, y)[0] << ", " << b.at(x, y)[1] << ", " << b.at(x, y)[2] << ")";
    EXPECT_EQ(differing, 0) << what << ": pixels that differ";
    EXPECT_EQ(cpu_stats.sdf_evals, gl_stats.sdf_evals) << what;
    EXPECT_EQ(cpu.sdf_eval_counts(), osmesa->sdf_eval_counts()) << what << ": evaluations a pixel";
    EXPECT_EQ(cpu.sample_counts(), osmesa->sample_counts()) << what;
    return cpu_stats.sdf_evals;
  }

  const SceneInfo* info = nullptr;
  bool meshes = false;    // a pose had a mesh pass, judged by Filament's rule
  bool bit_exact = true;  // this Mesa's llvmpipe gives the CPU's bits (gl/mesa_bits.h)
  CpuBackend cpu{2};
  std::unique_ptr<GlBackend> osmesa;
};

TEST_P(Agreement, BothBackendsGiveTheSameBits) {
  const std::vector<CameraPose> poses = test_camera_poses(*info);
  uint64_t evals = 0;
  for (size_t i = 0; i < poses.size(); ++i)
    evals +=
        expect_identical(context(*info, GetParam().mode, poses[i]), "pose " + std::to_string(i));
  // A marching case compares marched surfaces, not only background. A hit mask may be drawn
  // without counted evaluations (light_beams names the shape under the pixel directly), and a
  // parameter extreme may switch the scene's lights off: there the bits alone are compared.
  // A scene without marches (lenticular_card meets its boxes analytically) counts none.
  const Mode m = GetParam().mode;
  // Mesh passes count no SDF evaluations (museum's exhibit marches inside a mesh pass).
  const bool marches = !info->make()->distance_functions().empty();
  if (marches && !meshes &&
      (m == Mode::Draft || m == Mode::Final || m == Mode::Reference || m == Mode::Naive ||
       m == Mode::FinalAdaptive)) {
    EXPECT_GT(evals, uint64_t(W * H) * poses.size());
  }
}

std::vector<Case> cases() {
  std::vector<Case> out;
  for (const SceneInfo& s : all_scenes())
    for (Mode m : {Mode::Draft, Mode::Final, Mode::Reference, Mode::Naive, Mode::FinalHitMask,
                   Mode::NaiveHitMask, Mode::ParamsMin, Mode::ParamsMax, Mode::FinalAdaptive})
      out.push_back({s.name, m});
  return out;
}

std::string case_name(const ::testing::TestParamInfo<Case>& i) {
  static const char* const names[] = {"draft",      "final",         "reference",
                                      "naive",      "final_hitmask", "naive_hitmask",
                                      "params_min", "params_max",    "final_adaptive"};
  return i.param.scene + "_" + names[int(i.param.mode)];
}

INSTANTIATE_TEST_SUITE_P(Scenes, Agreement, ::testing::ValuesIn(cases()), case_name);

}  // namespace
}  // namespace sdfreel
