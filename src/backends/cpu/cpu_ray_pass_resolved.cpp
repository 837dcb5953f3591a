#include "backends/cpu/cpu_ray_pass_resolved.h"

#include <algorithm>
#include <vector>

#include "backends/cpu/trace_packet.h"
#include "render/tiling.h"

namespace sdfreel {

const RayPass* resolvable_ray_pass(const FramePlan& plan) {
  if (plan.passes.size() != 1 || !plan.setup_passes.empty()) return nullptr;
  const auto* ray = std::get_if<RayPass>(&plan.passes.front());
  if (!ray || !ray->packet || ray->colour != COLOUR_TARGET || !ray->depth.empty()) return nullptr;
  return ray;
}

namespace {

// Pairs a chunk holds at least (whole pixels, so a pixel's samples stay in one chunk and are
// summed in list order): enough packets to amortise a task, few enough to balance threads.
constexpr int CHUNK_PAIRS = 512;

struct SamplePair {
  int pixel, sample;  // pixel index in the frame, sample index in the list
};

struct Sums {
  ImageRGBA all, odd;      // all samples; those at odd list positions
  float* evals = nullptr;  // SDF evaluations of all samples, a value a pixel; null: none
};

// Traces pairs [from, to) eight at a time (the last packet padded with its last ray) and adds each
// result to its pixel's sums.
void trace_pairs(const RayPass& pass, const CpuPassContext& pc,
                 const std::vector<SamplePair>& pairs, int from, int to, const glm::vec3& clear,
                 Sums& sums, RayStats& stats) {
  const FrameContext& f = pc.frame;
  RayPassOutput result;
  for (int base = from; base < to; base += LANES) {
    const int count = to - base < LANES ? to - base : LANES;
    F8 x, y;
    for (int i = 0; i < LANES; ++i) {
      const SamplePair& p = pairs[size_t(base + (i < count ? i : count - 1))];
      const glm::vec2& o = f.sample_offsets[size_t(p.sample)];
      x[i] = float(p.pixel % f.width) + o.x;
      y[i] = float(p.pixel / f.width) + o.y;
    }
    trace_packet(pass, pc, x, y, count, result, stats);
    for (int i = 0; i < count; ++i) {
      const SamplePair& p = pairs[size_t(base + i)];
      const glm::vec3 c = result.keep[i] ? result.colour[i] : clear;
      float* s = &sums.all.pixels[size_t(p.pixel) * 4];
      s[0] += c.x;
      s[1] += c.y;
      s[2] += c.z;
      if (sums.evals && result.keep[i]) sums.evals[p.pixel] += float(result.evals[i]);
      if (p.sample & 1) {
        float* o = &sums.odd.pixels[size_t(p.pixel) * 4];
        o[0] += c.x;
        o[1] += c.y;
        o[2] += c.z;
      }
    }
  }
}

// The frame's pixels tile by tile (row-major inside a tile): neighbouring rays share packets.
std::vector<int> pixels_by_tile(int width, int height, int tile_size) {
  std::vector<int> order;
  order.reserve(size_t(width) * height);
  for (int ty = 0; ty < height; ty += tile_size)
    for (int tx = 0; tx < width; tx += tile_size)
      for (int y = ty; y < std::min(height, ty + tile_size); ++y)
        for (int x = tx; x < std::min(width, tx + tile_size); ++x) order.push_back(y * width + x);
  return order;
}

// One round: samples [from, to) of every live pixel, in chunks of whole pixels across threads.
void run_round(const RayPass& pass, const CpuPassContext& pc, const std::vector<int>& order,
               const LivePixels& live, int from, int to, const glm::vec3& clear, Sums& sums,
               RayStats& stats) {
  std::vector<SamplePair> pairs;
  // Room for every pixel's samples at once: growing by doubling copied tens of megabytes into
  // freshly faulted pages (a quarter of a card frame's page faults).
  pairs.reserve(order.size() * size_t(to - from));
  std::vector<int> chunk_starts;
  for (int pixel : order) {
    if (!live.live(size_t(pixel))) continue;
    if (chunk_starts.empty() || int(pairs.size()) - chunk_starts.back() >= CHUNK_PAIRS)
      chunk_starts.push_back(int(pairs.size()));
    for (int s = from; s < to; ++s) pairs.push_back({pixel, s});
  }
  const int chunks = int(chunk_starts.size());
  chunk_starts.push_back(int(pairs.size()));
  std::vector<RayStats> chunk_stats(static_cast<size_t>(chunks));
  for_each_index(size_t(chunks), pc.threads, [&](size_t c) {
    trace_pairs(pass, pc, pairs, chunk_starts[c], chunk_starts[c + 1], clear, sums, chunk_stats[c]);
  });
  for (const RayStats& s : chunk_stats) stats.add(s);
}

}  // namespace

ImageRGBA run_ray_pass_resolved(const RayPass& pass, const CpuPassContext& pc,
                                const glm::vec4& clear, RayStats& stats, SampleCounts* counts,
                                std::vector<float>* evals) {
  const FrameContext& f = pc.frame;
  const AdaptiveSampling a = sampling_of(f);
  Sums sums{ImageRGBA(f.width, f.height), ImageRGBA(f.width, f.height)};
  if (evals) {
    evals->assign(size_t(f.width) * f.height, 0.0f);
    if (!pass.sdf_evals.empty()) sums.evals = evals->data();
  }
  LivePixels live(a, f.width, f.height, pc.threads);
  const std::vector<int> order = pixels_by_tile(f.width, f.height, pc.tile_size);
  for (int from = 0;;) {
    const int to = live.round_end();
    run_round(pass, pc, order, live, from, to, glm::vec3(clear), sums, stats);
    from = to;
    if (to >= a.maximum || live.decide(to, sums.all, sums.odd) == 0) break;
  }
  normalise_sums(sums.all, live.counts());
  if (counts) *counts = live.counts();
  return std::move(sums.all);
}

}  // namespace sdfreel
