#include "backends/cpu/cpu_backend.h"

#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <vector>

#include "backends/cpu/plan_runner.h"
#include "render/tiling.h"

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
  with_threads(threads_, [&] { scene_->prepare(ctx); });
  return run_plan_cpu(scene_->frame_plan(ctx), ctx, CpuRunSettings{threads_, tile_size_, packets_},
                      stats, &counts_, record_evals_ ? &evals_ : nullptr);
}

}  // namespace sdfreel
