#include "backends/cpu/cpu_mesh_pass.h"

#include <stdexcept>

#include "backends/cpu/mesh_rasterise.h"
#include "backends/cpu/mesh_setup.h"

namespace sdfreel {

namespace {

// Clip space of the pass: its own view, or the plan's camera moved by the sample offset.
glm::mat4 view_projection(const MeshPass& pass, const CpuPassContext& pc) {
  if (pass.view) return pass.view->projection * pass.view->view;
  return sample_projection(pc.camera, pc.offset, pc.frame.width, pc.frame.height) * pc.camera.view;
}

}  // namespace

MeshPassCache::MeshPassCache() : data_(std::make_unique<Data>()) {}
MeshPassCache::~MeshPassCache() = default;
MeshPassCache::MeshPassCache(MeshPassCache&&) noexcept = default;

void run_mesh_pass(const MeshPass& pass, const CpuPassContext& pc, CpuTargets& targets,
                   MeshPassCache& cache) {
  if (!pass.mesh) throw std::runtime_error("mesh pass '" + pass.name + "' has no mesh");
  if (!pass.shade && !pass.shade_depth && !pass.colour.empty())
    throw std::runtime_error("mesh pass '" + pass.name + "' has no CPU code");
  MeshTargets out{pass.colour.empty() ? nullptr : &targets.get(pass.colour, pass.name), nullptr,
                  false, false, nullptr};
  if (!pass.depth.empty()) {
    out.depth = &targets.get(pass.depth, pass.name);
    out.test = pass.depth_test != DepthTest::Off;
    out.write_depth = pass.depth_test != DepthTest::TestOnly;
  }
  if (!out.colour && !out.depth)
    throw std::runtime_error("mesh pass '" + pass.name + "' writes no target");
  ImageInputs inputs;
  for (const ImageInput& in : pass.inputs) {
    if (in.target == pass.colour || in.target == pass.depth)
      throw std::runtime_error("mesh pass '" + pass.name + "' reads its own target '" + in.target +
                               "'");
    inputs.images.push_back(&targets.get(in.target, pass.name));
  }
  out.inputs = &inputs;
  const ImageRGBA& drawn = out.colour ? *out.colour : *out.depth;
  if (out.colour && out.depth &&
      (out.depth->width != drawn.width || out.depth->height != drawn.height))
    throw std::runtime_error("mesh pass '" + pass.name + "': colour and depth sizes differ");
  const glm::ivec2 size(drawn.width, drawn.height);
  MeshPassCache::Data& d = cache.data();
  place_vertices(pass, pc.threads, d);
  const int tile_size = pc.mesh_tile_size();
  setup_batches(pass, view_projection(pass, pc), size, tile_size, pc.threads, d);
  const VertexArrays placed = d.placed();
  for_each_tile(size.x, size.y, tile_size, pc.threads, [&](const Tile& t) {
    for (const TriangleBatch& b : d.batches) {  // in mesh order
      const VertexArrays clipped = b.clipped();
      for (unsigned i : b.bins[size_t(t.index)]) {
        const RasterTriangle& s = b.triangles[i];
        rasterise(s, s.clipped ? clipped : placed, pass, t, size.y, out);
      }
    }
  });
}

}  // namespace sdfreel
