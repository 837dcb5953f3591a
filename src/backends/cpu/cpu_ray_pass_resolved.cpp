#include "backends/cpu/cpu_ray_pass_resolved.h"

#include <tbb/parallel_invoke.h>

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

struct Sums {
  ImageRGBA all, odd;      // all samples; those at odd list positions (empty: not kept)
  float* evals = nullptr;  // SDF evaluations of all samples, a value a pixel; null: none
};

// A round's (pixel, sample) pairs, never stored: pair k is sample `from + k % samples` of pixel
// `pixels[k / samples]` (tens of megabytes of pairs, written on one thread, cost a card frame
// more than a tenth of its time).
struct RoundPairs {
  const int* pixels;  // the live pixels, tile by tile
  int samples, from;  // samples a pixel takes this round, the first one's index
  int pixel(int k) const { return pixels[k / samples]; }
  int sample(int k) const { return from + k % samples; }
};

// Traces pairs [first, last) eight at a time (the last packet padded with its last ray) and adds
// each result to its pixel's sums.
void trace_pairs(const RayPass& pass, const CpuPassContext& pc, const RoundPairs& pairs, int first,
                 int last, const glm::vec3& clear, Sums& sums, RayStats& stats) {
  const FrameContext& f = pc.frame;
  RayPassOutput result;
  for (int base = first; base < last; base += LANES) {
    const int count = last - base < LANES ? last - base : LANES;
    F8 x, y;
    int pixel[LANES], sample[LANES];
    for (int i = 0; i < LANES; ++i) {
      const int k = base + (i < count ? i : count - 1);
      pixel[i] = pairs.pixel(k);
      sample[i] = pairs.sample(k);
      const glm::vec2& o = f.sample_offsets[size_t(sample[i])];
      x[i] = float(pixel[i] % f.width) + o.x;
      y[i] = float(pixel[i] / f.width) + o.y;
    }
    trace_packet(pass, pc, x, y, count, result, stats);
    // A pixel's samples are neighbours in the packet: added in list order in registers, each sum
    // loaded and stored once (added in memory, each addition waited on the store before it).
    for (int i = 0; i < count;) {
      const int p = pixel[i];
      float* s = &sums.all.pixels[size_t(p) * 4];
      float* o = sums.odd.pixels.empty() ? nullptr : &sums.odd.pixels[size_t(p) * 4];
      float all[3] = {s[0], s[1], s[2]}, odd[3] = {};
      if (o) odd[0] = o[0], odd[1] = o[1], odd[2] = o[2];
      float evals = sums.evals ? sums.evals[p] : 0.0f;
      for (; i < count && pixel[i] == p; ++i) {
        const glm::vec3 c = result.keep[i] ? result.colour[i] : clear;
        all[0] += c.x;
        all[1] += c.y;
        all[2] += c.z;
        if (result.keep[i]) evals += float(result.evals[i]);
        if ((sample[i] & 1) && o) odd[0] += c.x, odd[1] += c.y, odd[2] += c.z;
      }
      s[0] = all[0], s[1] = all[1], s[2] = all[2];
      if (sums.evals) sums.evals[p] = evals;
      if (o) o[0] = odd[0], o[1] = odd[1], o[2] = odd[2];
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

// One round: samples [from, to) of every live pixel, in chunks of whole pixels across threads,
// each chunk the fewest pixels that hold CHUNK_PAIRS pairs.
void run_round(const RayPass& pass, const CpuPassContext& pc, const std::vector<int>& order,
               const LivePixels& live, int from, int to, const glm::vec3& clear, Sums& sums,
               RayStats& stats) {
  std::vector<int> live_order;  // while every pixel is live, `order` itself
  if (!live.all_live())
    for (int pixel : order)
      if (live.live(size_t(pixel))) live_order.push_back(pixel);
  const std::vector<int>& pixels = live.all_live() ? order : live_order;
  const RoundPairs pairs{pixels.data(), to - from, from};
  const int chunk_pixels = (CHUNK_PAIRS + pairs.samples - 1) / pairs.samples;
  const int count = int(pixels.size());
  const int chunks = (count + chunk_pixels - 1) / chunk_pixels;
  std::vector<RayStats> chunk_stats(static_cast<size_t>(chunks));
  for_each_index(size_t(chunks), pc.threads, [&](size_t c) {
    const int first = int(c) * chunk_pixels, last = std::min(count, first + chunk_pixels);
    trace_pairs(pass, pc, pairs, first * pairs.samples, last * pairs.samples, clear, sums,
                chunk_stats[c]);
  });
  for (const RayStats& s : chunk_stats) stats.add(s);
}

}  // namespace

ImageRGBA run_ray_pass_resolved(const RayPass& pass, const CpuPassContext& pc,
                                const glm::vec4& clear, RayStats& stats, SampleCounts* counts,
                                std::vector<float>* evals) {
  const FrameContext& f = pc.frame;
  const AdaptiveSampling a = sampling_of(f);
  LivePixels live(a, f.width, f.height, pc.threads);
  // Tens of megabytes of fresh, zeroed memory: each buffer filled on a thread of its own; the odd
  // samples' sums only when a decision will read them (adaptive sampling).
  Sums sums;
  std::vector<int> order;
  with_threads(pc.threads, [&] {
    tbb::parallel_invoke([&] { sums.all = ImageRGBA(f.width, f.height); },
                         [&] {
                           if (live.decides()) sums.odd = ImageRGBA(f.width, f.height);
                         },
                         [&] { order = pixels_by_tile(f.width, f.height, pc.tile_size); });
  });
  if (evals) {
    evals->assign(size_t(f.width) * f.height, 0.0f);
    if (!pass.sdf_evals.empty()) sums.evals = evals->data();
  }
  for (int from = 0;;) {
    const int to = live.round_end();
    run_round(pass, pc, order, live, from, to, glm::vec3(clear), sums, stats);
    from = to;
    if (to >= a.maximum || live.decide(to, sums.all, sums.odd) == 0) break;
  }
  normalise_sums(sums.all, live.counts(), pc.threads);
  if (counts) *counts = live.counts();
  return std::move(sums.all);
}

}  // namespace sdfreel
