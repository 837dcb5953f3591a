#pragma once
// A mesh pass on the CPU for one sample: a deterministic rasteriser with GL's rules, so it covers
// the pixels llvmpipe covers. Clip space from the camera model (the projection moved by the
// sample offset, so the pixel centre is the sample position); clipping against the near plane;
// coverage at pixel centres with the top-left rule (a pixel on a shared edge belongs to exactly
// one triangle); window depth z_w interpolated linearly in window space, varyings perspective-
// correct; depth test LESS, cull by winding (counter-clockwise in window space = front), alpha
// discard. Tiles run in parallel, each walking all triangles in mesh order, so every pixel sees
// its fragments in the same order whatever the thread count.
#include <memory>

#include "backends/cpu/cpu_pass_context.h"
#include "backends/cpu/cpu_targets.h"
#include "render/frame_plan.h"

namespace sdfreel {

// What one mesh pass keeps from sample to sample of a frame: its vertices after the vertex stage
// (world positions and normals do not depend on the sample offset, so `place` runs once per vertex
// and frame, not per triangle corner and sample; the same function of the same inputs, so the
// same bits) and its triangle buffers. Valid for one plan's pass for the duration of a frame.
class MeshPassCache {
 public:
  struct Data;
  MeshPassCache();
  ~MeshPassCache();
  MeshPassCache(MeshPassCache&&) noexcept;
  Data& data() { return *data_; }

 private:
  std::unique_ptr<Data> data_;
};

void run_mesh_pass(const MeshPass& pass, const CpuPassContext& pc, CpuTargets& targets,
                   MeshPassCache& cache);

}  // namespace sdfreel
