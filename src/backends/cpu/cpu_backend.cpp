#include "backends/cpu/cpu_backend.h"

#include <stdexcept>
#include <vector>

#include "render/tiling.h"

namespace sdfreel {

std::map<std::string, std::string> CpuBackend::versions() const {
  return {{"compiler", __VERSION__}, {"fp", "ffp-contract=off, no fast-math"}};
}

void CpuBackend::begin(const SceneInfo& scene) {
  scene_ = scene.make ? scene.make() : nullptr;
  if (!scene_) throw std::runtime_error("scene '" + scene.name + "' has no CPU implementation");
}

ImageRGBA CpuBackend::render(const FrameContext& ctx, RayStats& stats) {
  scene_->prepare(ctx);
  ImageRGBA img(ctx.width, ctx.height);
  const int n_tiles = tile_count(ctx.width, ctx.height, tile_size_);
  std::vector<RayStats> tile_stats(n_tiles);
  // Angular size of one pixel at the image centre, capped (quality.h): the hit epsilon grows with
  // t * pixel_angle.
  const float pixel_angle = footprint_angle(ctx.camera.tan_half_fov, ctx.height);
  const float inv_samples = 1.0f / float(ctx.sample_offsets.size());
  const Scene& scene = *scene_;
  for_each_tile(ctx.width, ctx.height, tile_size_, threads_, [&](const Tile& t) {
    RayStats& st = tile_stats[t.index];
    for (int y = t.y0; y < t.y1; ++y)
      for (int x = t.x0; x < t.x1; ++x) {
        glm::vec3 sum(0.0f);
        for (const glm::vec2& o : ctx.sample_offsets) {
          const glm::vec3 dir =
              primary_ray_dir(ctx.camera, float(x) + o.x, float(y) + o.y, ctx.width, ctx.height);
          sum += scene.radiance(Ray{ctx.camera.origin, dir, pixel_angle}, st);
        }
        float* p = img.at(x, y);
        p[0] = sum.x * inv_samples;
        p[1] = sum.y * inv_samples;
        p[2] = sum.z * inv_samples;
        p[3] = 1.0f;
      }
  });
  for (const RayStats& s : tile_stats) stats.add(s);
  return img;
}

}  // namespace sdfreel
