#include "raster_ids.h"

#include <atomic>
#include <cmath>
#include <stdexcept>

#include "backends/cpu/cpu_mesh_pass.h"
#include "backends/cpu/cpu_pass_context.h"
#include "backends/cpu/cpu_targets.h"
#include "render/quality.h"

namespace sdfreel::mesh_bench {
namespace {

std::atomic<uint64_t> alpha_tests{0};

constexpr uint32_t MAX_IDS = 1u << 24;  // ids ride in a float: exact below 2^24

CpuPassContext pass_context(const BenchCase& c, int sample, int threads) {
  return CpuPassContext{c.ctx,    c.ctx.sample_offsets[size_t(sample)],
                        c.camera, footprint_angle(c.ctx.camera.tan_half_fov, c.ctx.height),
                        threads,  16,
                        true};
}

MeshPass id_pass(const BenchCase& c, const FlatTriangles& flat, size_t p) {
  const MeshPass& scene_pass = c.passes[p];
  auto mesh = std::make_shared<TriangleMesh>();
  for (uint32_t t = flat.first_of_pass[p]; t < flat.first_of_pass[p + 1]; ++t)
    for (int k = 0; k < 3; ++k) {
      const glm::vec3& w = flat.world[t * 3 + uint32_t(k)];
      const glm::vec2& uv = flat.uv[t * 3 + uint32_t(k)];
      mesh->positions.insert(mesh->positions.end(), {w.x, w.y, w.z});
      mesh->normals.insert(mesh->normals.end(), {float(t), 0.0f, 0.0f});
      mesh->uvs.insert(mesh->uvs.end(), {uv.x, uv.y});
    }
  MeshPass pass;
  pass.name = scene_pass.name + " ids";
  pass.mesh = mesh;
  pass.depth_test = scene_pass.depth_test;
  pass.cull = scene_pass.cull;
  pass.alpha_cutoff = scene_pass.alpha_cutoff;
  const bool alpha = scene_pass.alpha_cutoff > 0.0f;
  const MeshPass* original = &scene_pass;
  const FlatTriangles* f = &flat;
  pass.shade = [alpha, original, f](const MeshFragment& frag) {
    const uint32_t id = uint32_t(std::lround(frag.world_normal.x));
    float a = 1.0f;
    if (alpha) {
      alpha_tests.fetch_add(1, std::memory_order_relaxed);
      MeshFragment g = frag;
      g.instance_data = original->instances[f->instance_of[id]].data;
      g.world_normal = glm::vec3(0.0f, 1.0f, 0.0f);  // alpha never reads it
      a = original->shade(g).a;
    }
    return glm::vec4(float(id + 1), 0.0f, 0.0f, a);
  };
  return pass;
}

}  // namespace

uint64_t take_raster_alpha_tests() {
  return alpha_tests.exchange(0);
}

RasterIds::RasterIds(const BenchCase& c, const FlatTriangles& flat) : case_(c) {
  if (flat.count() >= MAX_IDS) throw std::runtime_error("too many triangles for float ids");
  for (size_t p = 0; p < c.passes.size(); ++p) id_passes_.push_back(id_pass(c, flat, p));
}

SampleHits RasterIds::run(int threads) const {
  const FrameContext& f = case_.ctx;
  SampleHits out(f.width, f.height, int(f.sample_offsets.size()));
  CpuTargets targets(plan_targets(FramePlan{}), f.width, f.height);
  std::vector<MeshPassCache> caches(id_passes_.size());  // the frame's vertex stage, as the runner
  for (int s = 0; s < out.samples; ++s) {
    targets.clear();
    const CpuPassContext pc = pass_context(case_, s, threads);
    for (size_t p = 0; p < id_passes_.size(); ++p)
      run_mesh_pass(id_passes_[p], pc, targets, caches[p]);
    const ImageRGBA& ids = targets.get(COLOUR_TARGET, "bench");
    const ImageRGBA& depth = targets.get(DEPTH_TARGET, "bench");
    for (int y = 0; y < f.height; ++y)
      for (int x = 0; x < f.width; ++x) {
        out.id[out.index(s, x, y)] = uint32_t(ids.at(x, y)[0]);
        out.depth[out.index(s, x, y)] = depth.at(x, y)[0];
      }
  }
  return out;
}

SampleHits run_scene_passes(const BenchCase& c, int threads) {
  const FrameContext& f = c.ctx;
  SampleHits out(f.width, f.height, int(f.sample_offsets.size()));
  CpuTargets targets(c.targets, f.width, f.height);
  std::vector<MeshPassCache> caches(c.passes.size());  // the frame's vertex stage, as the runner
  for (int s = 0; s < out.samples; ++s) {
    targets.clear();
    const CpuPassContext pc = pass_context(c, s, threads);
    for (size_t p = 0; p < c.passes.size(); ++p) run_mesh_pass(c.passes[p], pc, targets, caches[p]);
    const ImageRGBA& depth = targets.get(c.passes.front().depth, "bench");
    for (int y = 0; y < f.height; ++y)
      for (int x = 0; x < f.width; ++x) out.depth[out.index(s, x, y)] = depth.at(x, y)[0];
  }
  return out;
}

}  // namespace sdfreel::mesh_bench
