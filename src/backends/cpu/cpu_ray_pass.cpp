#include "backends/cpu/cpu_ray_pass.h"

#include <stdexcept>
#include <vector>

#include "backends/cpu/trace_packet.h"
#include "render/tiling.h"

namespace sdfreel {

namespace {

struct RayPassTargets {
  ImageRGBA* colour;
  ImageRGBA* depth;  // null: none
  bool test, write_depth;
  ImageRGBA* evals;  // null: not counted
};

// One ray's result into the targets, as GL's fragment stage would: discard, depth test, writes.
void store(const RayPassTargets& t, int x, int y, const glm::vec3& colour, float depth, bool keep,
           int32_t evals) {
  if (!keep) return;
  if (t.depth) {
    float* d = t.depth->at(x, y);
    if (t.test && !(depth < d[0])) return;
    if (t.write_depth) d[0] = depth;
  }
  if (t.evals) t.evals->at(x, y)[0] = float(evals);
  float* p = t.colour->at(x, y);
  p[0] = colour.x;
  p[1] = colour.y;
  p[2] = colour.z;
  p[3] = 1.0f;
}

void tile_scalar(const RayPass& pass, const CpuPassContext& pc, const Tile& t,
                 const RayPassTargets& out, RayStats& stats) {
  const FrameContext& f = pc.frame;
  for (int y = t.y0; y < t.y1; ++y)
    for (int x = t.x0; x < t.x1; ++x) {
      const glm::vec3 dir = primary_ray_dir(f.camera, float(x) + pc.offset.x,
                                            float(y) + pc.offset.y, f.width, f.height);
      glm::vec3 colour(0.0f);
      float depth = 1.0f;
      bool keep = false;
      const uint64_t before = stats.sdf_evals;
      pass.scalar(Ray{f.camera.origin, dir, pc.pixel_angle}, colour, depth, keep, stats);
      store(out, x, y, colour, depth, keep, int32_t(stats.sdf_evals - before));
    }
}

// The tile's pixels in row order, eight at a time (the last packet padded with its last ray).
void tile_packets(const RayPass& pass, const CpuPassContext& pc, const Tile& t,
                  const RayPassTargets& out, RayStats& stats) {
  const int tw = t.x1 - t.x0, n = tw * (t.y1 - t.y0);
  RayPassOutput result;
  for (int base = 0; base < n; base += LANES) {
    const int count = n - base < LANES ? n - base : LANES;
    F8 x, y;
    for (int i = 0; i < LANES; ++i) {
      const int k = base + (i < count ? i : count - 1);
      x[i] = float(t.x0 + k % tw) + pc.offset.x;
      y[i] = float(t.y0 + k / tw) + pc.offset.y;
    }
    trace_packet(pass, pc, x, y, count, result, stats);
    for (int i = 0; i < count; ++i) {
      const int k = base + i;
      store(out, t.x0 + k % tw, t.y0 + k / tw, result.colour[i], result.depth[i], result.keep[i],
            result.evals[i]);
    }
  }
}

// What store() does at every pixel of the frame for a pass whose rays all give `colour`, kept,
// counting no SDF evaluation.
void fill_uniform(const glm::vec3& colour, const FrameContext& f, const RayPassTargets& out,
                  int threads) {
  for_each_range(size_t(f.height), 16, threads, [&](size_t begin, size_t end) {
    for (int y = int(begin); y < int(end); ++y)
      for (int x = 0; x < f.width; ++x) store(out, x, y, colour, 1.0f, true, 0);
  });
}

}  // namespace

void run_ray_pass(const RayPass& pass, const CpuPassContext& pc, CpuTargets& targets,
                  RayStats& stats) {
  // Packets unless asked for single rays (and the pass has them), or the pass has no packet code.
  const bool packets = pass.packet && (pc.packets || !pass.scalar);
  if (!packets && !pass.scalar)
    throw std::runtime_error("ray pass '" + pass.name + "' has no CPU code");
  RayPassTargets out{&targets.get(pass.colour, pass.name), nullptr, false, false, nullptr};
  if (!pass.sdf_evals.empty()) out.evals = &targets.get(pass.sdf_evals, pass.name);
  if (!pass.depth.empty()) {
    out.depth = &targets.get(pass.depth, pass.name);
    out.test = pass.depth_test != DepthTest::Off;
    out.write_depth = pass.depth_test != DepthTest::TestOnly;
  }
  const FrameContext& f = pc.frame;
  if (pass.uniform_colour && !out.depth)
    return fill_uniform(*pass.uniform_colour, f, out, pc.threads);
  std::vector<RayStats> tile_stats(size_t(tile_count(f.width, f.height, pc.tile_size)));
  for_each_tile(f.width, f.height, pc.tile_size, pc.threads, [&](const Tile& t) {
    if (packets)
      tile_packets(pass, pc, t, out, tile_stats[size_t(t.index)]);
    else
      tile_scalar(pass, pc, t, out, tile_stats[size_t(t.index)]);
  });
  for (const RayStats& s : tile_stats) stats.add(s);
}

}  // namespace sdfreel
