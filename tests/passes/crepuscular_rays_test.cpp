// The crepuscular-rays image pass on the CPU: the analytic check over uniform occlusion (GPU Gems
// 3 ch. 13 summed in closed form), the fade for a light behind the camera, and the jitter.
#include "render/passes/crepuscular_rays.h"

#include <gtest/gtest.h>

#include "backends/cpu/plan_runner.h"
#include "passes/plan_fixture.h"

namespace sdfreel {
namespace {

struct Case {
  float c, weight, decay, exposure;
};

ImageRGBA render_rays(const CrepuscularRays& rays, bool pattern, float c, int w, int h,
                      int threads = 1, int tile = 16) {
  FramePlan plan;
  plan.targets = {{"occlusion", TargetKind::Colour, glm::vec4(0.0f)}};
  plan.passes = {test::occlusion_fill("occlusion", pattern, c),
                 crepuscular_rays_pass(rays, "occlusion", COLOUR_TARGET)};
  RayStats stats;
  return run_plan_cpu(plan, test::plan_context(w, h), CpuRunSettings{threads, tile, true}, stats);
}

// The march stays between the pixel and a light at the centre (density < N / (N + 1)), so every
// pixel sums all N taps of a uniform c. The sum of N float terms rounds at most N half-ulps of its
// value; dyadic parameters (second case) make every step exact.
TEST(CrepuscularRays, UniformOcclusionGivesTheClosedForm) {
  for (const Case k : {Case{0.7f, 0.044140625f, 1.0f, 0.0034f}, Case{0.5f, 0.0078125f, 1.0f, 0.25f},
                       Case{1.0f, 0.3f, 0.97f, 0.05f}, Case{0.25f, 0.9f, 0.5f, 1.0f}}) {
    CrepuscularRays rays;
    rays.weight = k.weight;
    rays.decay = k.decay;
    rays.exposure = k.exposure;
    const ImageRGBA img = render_rays(rays, false, k.c, 24, 14);
    const double want =
        test::crepuscular_closed_form(k.c, rays.samples, k.weight, k.decay, k.exposure);
    const double tolerance = rays.samples * want * 0x1p-24;
    for (int y = 0; y < img.height; ++y) {
      for (int x = 0; x < img.width; ++x) {
        ASSERT_NEAR(img.at(x, y)[0], want, tolerance) << "pixel " << x << "," << y;
      }
    }
    if (k.weight == 0.0078125f) {
      EXPECT_EQ(img.at(3, 5)[0], 0.25f);  // 0.25 * 0.5 * (1 + 1), exact
    }
  }
}

TEST(CrepuscularRays, LightBehindTheCameraFadesToNothing) {
  const CameraBasis b = make_camera_basis({{0, 1, -5}, {0, 1, 0}, 50.0, 0.0});
  const CameraModel cam = make_camera_model(b, 32, 18, 0.05f, 500.0f);
  CrepuscularRays rays;
  crepuscular_light(rays, cam, -b.forward);
  EXPECT_EQ(rays.fade, 0.0f);
  const ImageRGBA img = render_rays(rays, false, 1.0f, 32, 18);
  for (size_t i = 0; i < img.pixels.size(); i += 4) {
    ASSERT_EQ(img.pixels[i], 0.0f);
  }
  crepuscular_light(rays, cam, b.forward);  // straight ahead: centre of the image, full strength
  EXPECT_EQ(rays.fade, 1.0f);
  EXPECT_NEAR(rays.light_uv.x, 0.5f, 1e-6f);
  EXPECT_NEAR(rays.light_uv.y, 0.5f, 1e-6f);
  crepuscular_light(rays, cam, glm::normalize(b.forward + b.up * 0.2f));  // above the centre
  EXPECT_LT(rays.light_uv.y, 0.5f);
  // Off screen at 72 degrees from the view axis: past FADE_START_COS, fading.
  crepuscular_light(rays, cam, glm::normalize(b.forward + b.right * 3.0f));
  EXPECT_GT(rays.light_uv.x, 1.0f);
  EXPECT_GT(rays.fade, 0.0f);
  EXPECT_LT(rays.fade, 1.0f);
}

// Threads and tiles never change bits; the jitter makes neighbouring pixels march different taps.
TEST(CrepuscularRays, PatternIsIndependentOfThreadsAndJittered) {
  CrepuscularRays rays;
  rays.light_uv = glm::vec2(0.8f, 0.3f);
  const ImageRGBA one = render_rays(rays, true, 0.0f, 40, 22, 1, 16);
  const ImageRGBA two = render_rays(rays, true, 0.0f, 40, 22, 2, 7);
  EXPECT_EQ(one.pixels, two.pixels);
  rays.jitter_seed = 5;
  const ImageRGBA other = render_rays(rays, true, 0.0f, 40, 22);
  EXPECT_NE(one.pixels, other.pixels);
}

}  // namespace
}  // namespace sdfreel
