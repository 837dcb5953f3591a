#pragma once
// A scene through its Scene interface at a tiny size, with a plain pixel loop (one ray through
// each pixel centre, like the CPU backend with one sample): what the scenes' own tests look at.
#include <cmath>
#include <memory>
#include <vector>

#include "render/camera.h"
#include "render/frame_context.h"
#include "render/quality.h"
#include "scenes/scene.h"

namespace sdfreel::test {

// The scene's default camera and parameters at `time`.
inline FrameContext scene_context(const SceneInfo& info, int width, int height, double time,
                                  Quality q) {
  FrameContext ctx;
  ctx.width = width;
  ctx.height = height;
  ctx.scene_time = time;
  ctx.quality = q;
  ctx.pose = info.default_camera;
  ctx.params = ParamValues(&info.params);
  finish_frame_context(ctx);
  return ctx;
}

struct ScenePixels {
  int width = 0;
  std::vector<glm::vec3> px;  // row-major
  RayStats stats;
  const glm::vec3& at(int x, int y) const { return px[size_t(y) * size_t(width) + size_t(x)]; }
};

inline ScenePixels render_pixels(const SceneInfo& info, const FrameContext& ctx) {
  std::unique_ptr<Scene> scene = info.make();
  scene->prepare(ctx);
  const float pixel_angle = footprint_angle(ctx.camera.tan_half_fov, ctx.height);
  ScenePixels img;
  img.width = ctx.width;
  for (int y = 0; y < ctx.height; ++y)
    for (int x = 0; x < ctx.width; ++x) {
      const glm::vec3 d = primary_ray_dir(ctx.camera, x + 0.5f, y + 0.5f, ctx.width, ctx.height);
      img.px.push_back(scene->radiance(Ray{ctx.camera.origin, d, pixel_angle}, img.stats));
    }
  return img;
}

// Mean over pixels and channels of |a - b|.
inline double mean_abs_difference(const ScenePixels& a, const ScenePixels& b) {
  double sum = 0.0;
  for (size_t i = 0; i < a.px.size(); ++i) {
    const glm::vec3 d = glm::abs(a.px[i] - b.px[i]);
    sum += d.x + d.y + d.z;
  }
  return sum / (3.0 * double(a.px.size()));
}

}  // namespace sdfreel::test
