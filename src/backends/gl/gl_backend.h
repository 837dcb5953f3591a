#pragma once
// The GL backend: a scene's GLSL twin (shaders/<scene>.glsl) on a GL platform (EGL or OSMesa,
// gl_platform_choice.h), by default Mesa's llvmpipe. Per frame it
// runs the C++ scene's prepare() for its per-frame constants and its frame plan, hands the shaders
// the same FrameContext the CPU backend reads, runs the plan's passes (gl_plan_runner.h) and
// reads the linear image back.
#include <memory>

#include "backends/gl/gl_driver.h"
#include "backends/gl/gl_plan_runner.h"
#include "backends/gl/gl_platform_choice.h"
#include "backends/gl/shadertoy_runner.h"
#include "render/backend.h"
#include "scenes/scene.h"

namespace sdfreel {

class GlBackend : public Backend {
 public:
  // Creates the context and finds the shader folder; throws GlPlatformError or ShaderError.
  explicit GlBackend(const GlChoice& choice = {});
  ~GlBackend() override;
  // The platform's name, egl or osmesa: manifests made with `--backend osmesa` keep their name.
  std::string name() const override { return platform_->name(); }
  // platform, device, mesa (e.g. 22.3.6), gl_renderer, gl_version.
  std::map<std::string, std::string> versions() const override;
  void begin(const SceneInfo& scene) override;
  ImageRGBA render(const FrameContext& ctx, RayStats& stats) override;
  const SampleCounts& sample_counts() const override { return counts_; }
  void record_sdf_evals(bool on) override { record_evals_ = on; }
  // Empty for a user's shader, which counts none.
  const std::vector<float>& sdf_eval_counts() const override { return evals_; }
  void set_frame_source(std::function<FrameContext(int)> source) override;
  void set_checkpoints(std::shared_ptr<BufferCheckpoints> checkpoints) override;

 private:
  void begin_shader(const SceneInfo& scene);
  std::unique_ptr<GlPlatform> platform_;
  int threads_;                                 // GlChoice::threads
  std::unique_ptr<GlDriver> driver_;            // destroyed before the platform (needs its context)
  std::unique_ptr<GlPlanRunner> runner_;        // destroyed before the driver
  std::unique_ptr<ShadertoyRunner> shadertoy_;  // a user's shader, instead of scene_
  std::shared_ptr<const ShaderProject> project_;
  std::function<FrameContext(int)> frame_source_;
  std::shared_ptr<BufferCheckpoints> checkpoints_;
  std::unique_ptr<Scene> scene_;
  std::string scene_shader_;
  std::vector<GlTextureBinding> textures_;  // uploaded for shader_textures_key() textures_key_
  uint64_t textures_key_ = 0;
  SampleCounts counts_;
  bool record_evals_ = false;
  std::vector<float> evals_;
};

}  // namespace sdfreel
