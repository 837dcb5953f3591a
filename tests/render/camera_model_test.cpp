// One camera model for rays and meshes: a point hit by a ray projects back onto the image
// position the ray was traced through, and the depth a ray pass writes for it (window_depth of
// t * dot(dir, forward)) equals the depth GL's rasteriser computes from clip space.
#include "render/camera_model.h"

#include <gtest/gtest.h>

#include <cmath>

namespace sdfreel {
namespace {

// Float rounding of the two paths. Depth: 8 ulps of z_w near 1 for the arithmetic, plus what the
// rounding of the hit point itself (8 ulps of |origin| + t, in world units) moves z_w by, which is
// large near the near plane (dz_w / dd = depth_scale * n / d^2). The next test pins the
// convention itself (0 at near, 1 at far, increasing). Image positions: 1e-3 pixels.
float depth_tolerance(const CameraModel& cam, const CameraBasis& b, float t, float d) {
  const float ulp = 0x1p-24f;
  const float point_error = 8.0f * (glm::length(b.origin) + t) * ulp;
  return 8.0f * ulp + cam.depth_scale * cam.near_plane / (d * d) * point_error;
}
constexpr float PIXEL_TOLERANCE = 1e-3f;

struct Projected {
  glm::vec2 image;  // pixels, origin top-left, y down
  float depth;      // window depth
};

Projected project(const glm::mat4& proj, const glm::mat4& view, const glm::vec3& p, int w, int h) {
  const glm::vec4 clip = proj * (view * glm::vec4(p, 1.0f));
  const glm::vec3 ndc = glm::vec3(clip) / clip.w;
  return {glm::vec2((ndc.x * 0.5f + 0.5f) * float(w), (0.5f - ndc.y * 0.5f) * float(h)),
          ndc.z * 0.5f + 0.5f};
}

TEST(CameraModel, RayHitAndProjectedPointShareImagePositionAndDepth) {
  const int w = 64, h = 36;
  for (const CameraPose& pose : {CameraPose{{0, 1, -5}, {0, 0, 0}, 50.0, 0.0},
                                 CameraPose{{3, 2.5, 4}, {-1, 0.5, 0}, 35.0, 12.0},
                                 CameraPose{{0, 10, 0}, {0, 0, 0}, 90.0, -30.0}}) {
    const CameraBasis b = make_camera_basis(pose);
    const CameraModel cam = make_camera_model(b, w, h, 0.05f, 500.0f);
    for (float px : {0.0f, 10.25f, 32.0f, 63.9f})
      for (float py : {0.0f, 17.5f, 35.9f})
        for (float t : {0.07f, 1.0f, 7.3f, 120.0f}) {
          const glm::vec3 dir = primary_ray_dir(b, px, py, w, h);
          const glm::vec3 hit = b.origin + dir * t;
          const float d = t * glm::dot(dir, b.forward);
          const float ray_depth = window_depth(cam, d);
          const Projected m = project(cam.projection, cam.view, hit, w, h);
          EXPECT_NEAR(m.image.x, px, PIXEL_TOLERANCE) << px << "," << py << " t " << t;
          EXPECT_NEAR(m.image.y, py, PIXEL_TOLERANCE) << px << "," << py << " t " << t;
          EXPECT_NEAR(m.depth, ray_depth, depth_tolerance(cam, b, t, d))
              << px << "," << py << " t " << t;
        }
  }
}

TEST(CameraModel, DepthConventionNearIsZeroFarIsOne) {
  const CameraModel cam = make_camera_model(make_camera_basis({}), 16, 9, 0.1f, 100.0f);
  EXPECT_NEAR(window_depth(cam, 0.1f), 0.0f, 1e-7f);
  EXPECT_NEAR(window_depth(cam, 100.0f), 1.0f, 1e-6f);
  EXPECT_LT(window_depth(cam, 2.0f), window_depth(cam, 2.001f));  // nearer is smaller: LESS
  // Round trip: one ulp of z_w is d^2 / n * 6e-8 in view depth (GL depth's known far precision).
  for (float d : {0.2f, 1.0f, 13.0f, 90.0f})
    EXPECT_NEAR(view_depth(cam, window_depth(cam, d)), d, 4.0f * d * d / 0.1f * 0x1p-24f);
}

TEST(CameraModel, SampleProjectionPutsTheSampleOnThePixelCentre) {
  const int w = 40, h = 30;
  const CameraBasis b = make_camera_basis({{1, 2, -6}, {0, 0.5f, 0}, 45.0, 5.0});
  const CameraModel cam = make_camera_model(b, w, h, 0.05f, 500.0f);
  for (const glm::vec2 o : {glm::vec2(0.5f), glm::vec2(0.1f, 0.9f), glm::vec2(0.77f, 0.02f)}) {
    const glm::mat4 proj = sample_projection(cam, o, w, h);
    // The ray a ray pass traces for pixel (x, y) and sample o lands on GL's pixel centre.
    for (int x : {0, 13, 39})
      for (int y : {0, 20, 29}) {
        const glm::vec3 dir = primary_ray_dir(b, float(x) + o.x, float(y) + o.y, w, h);
        const Projected m = project(proj, cam.view, b.origin + dir * 3.0f, w, h);
        EXPECT_NEAR(m.image.x, float(x) + 0.5f, PIXEL_TOLERANCE);
        EXPECT_NEAR(m.image.y, float(y) + 0.5f, PIXEL_TOLERANCE);
      }
  }
}

}  // namespace
}  // namespace sdfreel
