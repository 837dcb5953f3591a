#pragma once
// The CPU backend: the scene's C++ code over tiles on all cores, samples summed in fixed order.
#include <memory>

#include "render/backend.h"
#include "scenes/scene.h"

namespace sdfreel {

class CpuBackend : public Backend {
 public:
  CpuBackend(int threads, int tile_size = 16) : threads_(threads), tile_size_(tile_size) {}
  std::string name() const override { return "cpu"; }
  std::map<std::string, std::string> versions() const override;
  void begin(const SceneInfo& scene) override;
  ImageRGBA render(const FrameContext& ctx, RayStats& stats) override;

 private:
  int threads_, tile_size_;
  std::unique_ptr<Scene> scene_;
};

}  // namespace sdfreel
