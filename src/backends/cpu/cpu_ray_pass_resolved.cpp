#include "backends/cpu/cpu_ray_pass_resolved.h"

#include <vector>

#include "render/tiling.h"

namespace sdfreel {

const RayPass* resolvable_ray_pass(const FramePlan& plan) {
  if (plan.passes.size() != 1 || !plan.setup_passes.empty()) return nullptr;
  const auto* ray = std::get_if<RayPass>(&plan.passes.front());
  if (!ray || !ray->packet || ray->colour != COLOUR_TARGET || !ray->depth.empty()) return nullptr;
  return ray;
}

namespace {

struct PixelSums {
  glm::vec3 sum{0.0f}, odd{0.0f};  // all samples; those at odd list positions
  int taken = 0;
  bool live = true;
};

struct SamplePair {
  int pixel, sample;  // pixel index in the tile, sample index in the list
};

// Traces the pairs eight at a time (the last packet padded with its last ray) and adds each
// result to its pixel's sums. Pairs come pixel by pixel, samples in list order, so every pixel's
// samples are summed in list order.
void trace_pairs(const RayPass& pass, const CpuPassContext& pc, const Tile& t,
                 const std::vector<SamplePair>& pairs, const glm::vec3& clear,
                 std::vector<PixelSums>& px, RayStats& stats) {
  const FrameContext& f = pc.frame;
  const int tw = t.x1 - t.x0, n = int(pairs.size());
  RayPacket packet;
  packet.origin = f.camera.origin;
  packet.pixel_angle = pc.pixel_angle;
  RayPassOutput result;
  for (int base = 0; base < n; base += LANES) {
    packet.count = n - base < LANES ? n - base : LANES;
    for (int i = 0; i < LANES; ++i) {
      const SamplePair& p = pairs[size_t(base + (i < packet.count ? i : packet.count - 1))];
      const glm::vec2& o = f.sample_offsets[size_t(p.sample)];
      const float x = float(t.x0 + p.pixel % tw) + o.x, y = float(t.y0 + p.pixel / tw) + o.y;
      packet.dir.set_lane(i, primary_ray_dir(f.camera, x, y, f.width, f.height));
      result.keep[i] = false;
      result.depth[i] = 1.0f;
    }
    pass.packet(packet, result, stats);
    for (int i = 0; i < packet.count; ++i) {
      const SamplePair& p = pairs[size_t(base + i)];
      const glm::vec3 c = result.keep[i] ? result.colour[i] : clear;
      PixelSums& s = px[size_t(p.pixel)];
      s.sum += c;
      if (p.sample & 1) s.odd += c;
    }
  }
}

void add_pairs(int pixel, int from, int to, std::vector<SamplePair>& pairs) {
  for (int s = from; s < to; ++s) pairs.push_back({pixel, s});
}

void tile_resolved(const RayPass& pass, const CpuPassContext& pc, const AdaptiveSampling& a,
                   const Tile& t, const glm::vec3& clear, ImageRGBA& img, SampleCounts* counts,
                   RayStats& stats) {
  const int tw = t.x1 - t.x0, th = t.y1 - t.y0, n_pixels = tw * th;
  std::vector<PixelSums> px(static_cast<size_t>(n_pixels));
  std::vector<SamplePair> pairs;
  int end = first_round_samples(a);
  for (int p = 0; p < n_pixels; ++p) add_pairs(p, 0, end, pairs);
  while (!pairs.empty()) {
    trace_pairs(pass, pc, t, pairs, clear, px, stats);
    pairs.clear();
    const int next = next_round_end(a, end);
    for (int p = 0; p < n_pixels; ++p) {
      PixelSums& s = px[size_t(p)];
      if (!s.live) continue;
      s.taken = end;
      s.live = needs_more_samples(a, end, s.sum, s.odd);
      if (s.live) add_pairs(p, end, next, pairs);
    }
    end = next;
  }
  for (int j = 0; j < th; ++j)
    for (int i = 0; i < tw; ++i) {
      const PixelSums& s = px[size_t(j) * tw + i];
      const float inv_samples = 1.0f / float(s.taken);
      float* p = img.at(t.x0 + i, t.y0 + j);
      p[0] = s.sum.x * inv_samples;
      p[1] = s.sum.y * inv_samples;
      p[2] = s.sum.z * inv_samples;
      p[3] = 1.0f;
      if (counts) (*counts)[size_t(t.y0 + j) * img.width + t.x0 + i] = uint16_t(s.taken);
    }
}

}  // namespace

ImageRGBA run_ray_pass_resolved(const RayPass& pass, const CpuPassContext& pc,
                                const glm::vec4& clear, RayStats& stats, SampleCounts* counts) {
  const FrameContext& f = pc.frame;
  const AdaptiveSampling a = sampling_of(f);
  ImageRGBA img(f.width, f.height);
  if (counts) counts->assign(size_t(f.width) * f.height, 0);
  std::vector<RayStats> tile_stats(size_t(tile_count(f.width, f.height, pc.tile_size)));
  for_each_tile(f.width, f.height, pc.tile_size, pc.threads, [&](const Tile& t) {
    tile_resolved(pass, pc, a, t, glm::vec3(clear), img, counts, tile_stats[size_t(t.index)]);
  });
  for (const RayStats& s : tile_stats) stats.add(s);
  return img;
}

}  // namespace sdfreel
