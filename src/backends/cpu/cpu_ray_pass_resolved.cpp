#include "backends/cpu/cpu_ray_pass_resolved.h"

#include <vector>

#include "render/tiling.h"

namespace sdfreel {

const RayPass* resolvable_ray_pass(const FramePlan& plan) {
  if (plan.passes.size() != 1) return nullptr;
  const auto* ray = std::get_if<RayPass>(&plan.passes.front());
  if (!ray || !ray->packet || ray->colour != COLOUR_TARGET || !ray->depth.empty()) return nullptr;
  return ray;
}

namespace {

// The tile's (pixel, sample) pairs in pixel order, samples in list order, eight at a time; each
// pixel's samples summed in sample order, as the per-sample loop sums them.
void tile_resolved(const RayPass& pass, const CpuPassContext& pc, const Tile& t,
                   const glm::vec3& clear, ImageRGBA& img, RayStats& stats) {
  const FrameContext& f = pc.frame;
  const int n_samples = int(f.sample_offsets.size());
  const int tw = t.x1 - t.x0, th = t.y1 - t.y0, n = tw * th * n_samples;
  std::vector<glm::vec3> sums(size_t(tw) * th, glm::vec3(0.0f));
  RayPacket packet;
  packet.origin = f.camera.origin;
  packet.pixel_angle = pc.pixel_angle;
  RayPassOutput result;
  for (int base = 0; base < n; base += LANES) {
    packet.count = n - base < LANES ? n - base : LANES;
    for (int i = 0; i < LANES; ++i) {
      const int k = base + (i < packet.count ? i : packet.count - 1);
      const int pixel = k / n_samples;
      const glm::vec2& o = f.sample_offsets[size_t(k % n_samples)];
      const float x = float(t.x0 + pixel % tw) + o.x, y = float(t.y0 + pixel / tw) + o.y;
      packet.dir.set_lane(i, primary_ray_dir(f.camera, x, y, f.width, f.height));
      result.keep[i] = false;
      result.depth[i] = 1.0f;
    }
    pass.packet(packet, result, stats);
    for (int i = 0; i < packet.count; ++i)
      sums[size_t((base + i) / n_samples)] += result.keep[i] ? result.colour[i] : clear;
  }
  const float inv_samples = 1.0f / float(n_samples);
  for (int j = 0; j < th; ++j)
    for (int i = 0; i < tw; ++i) {
      const glm::vec3& s = sums[size_t(j) * tw + i];
      float* p = img.at(t.x0 + i, t.y0 + j);
      p[0] = s.x * inv_samples;
      p[1] = s.y * inv_samples;
      p[2] = s.z * inv_samples;
      p[3] = 1.0f;
    }
}

}  // namespace

ImageRGBA run_ray_pass_resolved(const RayPass& pass, const CpuPassContext& pc,
                                const glm::vec4& clear, RayStats& stats) {
  const FrameContext& f = pc.frame;
  ImageRGBA img(f.width, f.height);
  std::vector<RayStats> tile_stats(size_t(tile_count(f.width, f.height, pc.tile_size)));
  for_each_tile(f.width, f.height, pc.tile_size, pc.threads, [&](const Tile& t) {
    tile_resolved(pass, pc, t, glm::vec3(clear), img, tile_stats[size_t(t.index)]);
  });
  for (const RayStats& s : tile_stats) stats.add(s);
  return img;
}

}  // namespace sdfreel
