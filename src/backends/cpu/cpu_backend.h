#pragma once
// The CPU backend: the scene's frame plan (render/frame_plan.h) run by plan_runner, its passes
// over tiles on all cores, samples summed in fixed order. Ray passes get rays in packets of eight
// (Scene::radiance_packet, SIMD lanes) or one by one (Scene::radiance, `packets` false or
// SDFREEL_SIMD=0 in the environment): the same bits.
#include <memory>

#include "render/backend.h"
#include "render/tiling.h"
#include "scenes/scene.h"

namespace sdfreel {

class CpuBackend : public Backend {
 public:
  CpuBackend(int threads, int tile_size = 16, bool packets = packets_by_default())
      : threads_(threads), tile_size_(tile_size), packets_(packets) {}
  // True unless the environment says SDFREEL_SIMD=0 (for comparing the two paths).
  static bool packets_by_default();
  std::string name() const override { return "cpu"; }
  std::map<std::string, std::string> versions() const override;
  void begin(const SceneInfo& scene) override;
  ImageRGBA render(const FrameContext& ctx, RayStats& stats) override;
  const SampleCounts& sample_counts() const override { return counts_; }
  void record_sdf_evals(bool on) override { record_evals_ = on; }
  const std::vector<float>& sdf_eval_counts() const override { return evals_; }

 private:
  int threads_, tile_size_;
  bool packets_;
  std::unique_ptr<Scene> scene_;
  SampleCounts counts_;
  bool record_evals_ = false;
  std::vector<float> evals_;
};

}  // namespace sdfreel
