// The crepuscular-rays image pass on the CPU: the analytic check over uniform occlusion (GPU Gems
// 3 ch. 13 summed in closed form), the fade for a light behind the camera, and the jitter.
#include "render/passes/crepuscular_rays.h"

#include <gtest/gtest.h>

#include <cstring>

#include "backends/cpu/plan_runner.h"
#include "passes/plan_fixture.h"
#include "render/passes/crepuscular_rays_rows.h"

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

// The march stays between the pixel and a light at the centre (density 1: the last tap is short of
// the light by 1 - jitter steps), so every pixel sums all N taps of a uniform c. The sum of N float terms rounds at most N half-ulps of its
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
      EXPECT_EQ(img.at(3, 5)[0], 0.125f);  // 0.25 * 0.5 * 128 * 2^-7, exact
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

// An occlusion image of w x h: lit (1) inside the box [x0, x1) x [y0, y1), `outside` elsewhere.
ImageRGBA occlusion_window(int w, int h, int x0, int x1, int y0, int y1, float outside = 0.0f) {
  ImageRGBA occ(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const bool lit = x >= x0 && x < x1 && y >= y0 && y < y1;
      occ.at(x, y)[0] = lit ? 1.0f : outside;
    }
  return occ;
}

// The row function (lanes, lit-box skipping) against the pixel function, bit for bit: lights
// inside, at the border and off screen, a lane column straight below the light, decay below 1,
// spans that end mid-packet, and occlusion with -0 and negative texels (where nothing is skipped).
TEST(CrepuscularRays, RowsGiveThePixelFunctionsBits) {
  const int w = 37, h = 23;
  std::vector<ImageRGBA> images = {
      occlusion_window(w, h, 20, 27, 3, 9), occlusion_window(w, h, 0, 0, 0, 0),
      occlusion_window(w, h, 0, w, 0, h), occlusion_window(w, h, 30, 37, 15, 23, -0.0f),
      occlusion_window(w, h, 5, 9, 2, 20, -0.25f)};
  ImageRGBA pattern(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) pattern.at(x, y)[0] = test::occlusion_pattern(x, y) * 0.75f;
  images.push_back(pattern);
  const glm::vec2 lights[] = {{0.6f, 0.25f}, {(23.0f + 0.5f) / w, 0.3f},
                              {1.4f, -0.3f}, {-0.2f, 0.5f},
                              {0.5f, 1.0f},  {0.0f, 0.0f}};
  for (const ImageRGBA& occ : images)
    for (const glm::vec2 light : lights)
      for (const float decay : {1.0f, 0.97f}) {
        CrepuscularRays rays;
        rays.light_uv = light;
        rays.decay = decay;
        const ImagePass::RowFunction row = crepuscular_rays_rows(rays, occ);
        for (int y = 0; y < h; ++y)
          for (const auto& span : {std::pair<int, int>{0, w}, std::pair<int, int>{3, 14}}) {
            std::vector<float> out(size_t(4 * (span.second - span.first)), -1.0f);
            row(y, span.first, span.second, out.data());
            for (int x = span.first; x < span.second; ++x) {
              const glm::vec4 want = crepuscular_rays_pixel(rays, occ, x, y);
              ASSERT_EQ(std::memcmp(&out[size_t(4 * (x - span.first))], &want[0], 16), 0)
                  << "pixel " << x << "," << y << " light " << light.x << "," << light.y
                  << " decay " << decay << ": " << out[size_t(4 * (x - span.first))] << " vs "
                  << want.x;
            }
          }
      }
}

}  // namespace
}  // namespace sdfreel
