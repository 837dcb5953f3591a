#include "backends/cpu/cpu_backend.h"

#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <vector>

namespace sdfreel {

bool CpuBackend::packets_by_default() {
  const char* v = std::getenv("SDFREEL_SIMD");
  return !(v && (std::strcmp(v, "0") == 0 || std::strcmp(v, "off") == 0));
}

std::map<std::string, std::string> CpuBackend::versions() const {
#ifdef SDFREEL_ISA_AVX2
  const char* isa = "avx2";
#else
  const char* isa = "baseline";
#endif
  return {{"compiler", __VERSION__}, {"fp", "ffp-contract=off, no fast-math"}, {"isa", isa}};
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
  for_each_tile(ctx.width, ctx.height, tile_size_, threads_, [&](const Tile& t) {
    if (packets_)
      render_tile_packets(ctx, t, pixel_angle, img, tile_stats[t.index]);
    else
      render_tile_scalar(ctx, t, pixel_angle, img, tile_stats[t.index]);
  });
  for (const RayStats& s : tile_stats) stats.add(s);
  return img;
}

namespace {

void store_pixel(ImageRGBA& img, int x, int y, const glm::vec3& sum, float inv_samples) {
  float* p = img.at(x, y);
  p[0] = sum.x * inv_samples;
  p[1] = sum.y * inv_samples;
  p[2] = sum.z * inv_samples;
  p[3] = 1.0f;
}

}  // namespace

void CpuBackend::render_tile_scalar(const FrameContext& ctx, const Tile& t, float pixel_angle,
                                    ImageRGBA& img, RayStats& stats) const {
  const float inv_samples = 1.0f / float(ctx.sample_offsets.size());
  for (int y = t.y0; y < t.y1; ++y)
    for (int x = t.x0; x < t.x1; ++x) {
      glm::vec3 sum(0.0f);
      for (const glm::vec2& o : ctx.sample_offsets) {
        const glm::vec3 dir =
            primary_ray_dir(ctx.camera, float(x) + o.x, float(y) + o.y, ctx.width, ctx.height);
        sum += scene_->radiance(Ray{ctx.camera.origin, dir, pixel_angle}, stats);
      }
      store_pixel(img, x, y, sum, inv_samples);
    }
}

// The tile's (pixel, sample) pairs in the scalar loop's order, eight at a time: with many samples
// a packet holds samples of one pixel (coherent rays), with one sample a row of pixels. Each
// pixel's samples are summed in sample order, as in render_tile_scalar.
void CpuBackend::render_tile_packets(const FrameContext& ctx, const Tile& t, float pixel_angle,
                                     ImageRGBA& img, RayStats& stats) const {
  const int n_samples = int(ctx.sample_offsets.size());
  const int tw = t.x1 - t.x0, th = t.y1 - t.y0;
  const int n = tw * th * n_samples;
  std::vector<glm::vec3> sums(size_t(tw) * th, glm::vec3(0.0f));
  RayPacket packet;
  packet.origin = ctx.camera.origin;
  packet.pixel_angle = pixel_angle;
  glm::vec3 out[LANES];
  for (int base = 0; base < n; base += LANES) {
    packet.count = n - base < LANES ? n - base : LANES;
    for (int i = 0; i < LANES; ++i) {
      const int k = base + (i < packet.count ? i : packet.count - 1);
      const int pixel = k / n_samples;
      const glm::vec2& o = ctx.sample_offsets[k % n_samples];
      const float x = float(t.x0 + pixel % tw) + o.x, y = float(t.y0 + pixel / tw) + o.y;
      packet.dir.set_lane(i, primary_ray_dir(ctx.camera, x, y, ctx.width, ctx.height));
    }
    scene_->radiance_packet(packet, out, stats);
    for (int i = 0; i < packet.count; ++i) sums[(base + i) / n_samples] += out[i];
  }
  const float inv_samples = 1.0f / float(n_samples);
  for (int j = 0; j < th; ++j)
    for (int i = 0; i < tw; ++i)
      store_pixel(img, t.x0 + i, t.y0 + j, sums[size_t(j) * tw + i], inv_samples);
}

}  // namespace sdfreel
