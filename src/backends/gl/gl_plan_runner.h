#pragma once
// Runs a frame plan (render/frame_plan.h) on the GL driver: the per-frame targets are cleared and
// the setup passes drawn once; then per sample offset, in list order, the other targets are
// cleared and every pass drawn in plan order (ray and image passes as full-screen
// passes, mesh passes as instanced meshes); then one full-screen draw adds the sample's "colour"
// and "sdf_evals" into float sum targets (blend ONE + ONE: one IEEE add a channel, samples in list
// order, the CPU's order). The frame is the sum read back times 1 / count, on the host as on the
// CPU.
//
// Adaptive sampling (render/adaptive_sampling.h) in rounds: at the end of each round the sums
// (all samples, and odd list positions in a third sum target) are read back, the host decides
// which pixels go on with the CPU's code (render/live_pixels.h) and uploads a mask of live pixels;
// the accumulation adds only live pixels, and a plan of one ray pass discards stopped pixels
// before tracing. Fixed sampling is one round with every pixel live. A plan of one ray pass
// without depth traces its later rounds packed (live_pixel_packing.h): the live pixels fill the
// first rows, and the draw covers only those rows.
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "backends/gl/gl_driver.h"
#include "backends/gl/gl_targets.h"
#include "render/frame_context.h"
#include "render/frame_plan.h"
#include "render/live_pixels.h"

namespace sdfreel {

// What the scene adds to every pass: its shader (for ray passes that name none), its per-frame
// uniforms and textures.
struct GlSceneInputs {
  std::string shader;
  std::vector<ShaderUniform> uniforms;
  std::vector<GlTextureBinding> textures;
};

class GlPlanRunner {
 public:
  // threads: for the CPU work between draws (adaptive sampling's decisions).
  GlPlanRunner(GlDriver& driver, int threads)
      : driver_(driver), targets_(driver.gl()), threads_(threads) {}
  // `counts` and `evals` as run_plan_cpu's (backends/cpu/plan_runner.h).
  ImageRGBA run(const FramePlan& plan, const FrameContext& ctx, const GlSceneInputs& scene,
                RayStats& stats, SampleCounts* counts = nullptr,
                std::vector<float>* evals = nullptr);
  // Compiles (once) the program of a pass, for warm-up and error messages before the first frame.
  GlProgramId program(const std::string& vertex, const std::string& fragment);

 private:
  GlMeshId mesh(const std::shared_ptr<const TriangleMesh>& m);
  void run_pass(const Pass& pass, const GlSceneInputs& scene,
                const std::vector<ShaderUniform>& base, int packed_rows);
  void accumulate(bool odd, bool packed);
  void upload_packing(const std::vector<uint8_t>& live, int width, int height);
  void upload_live_mask(const std::vector<uint8_t>& live, int width, int height);

  GlDriver& driver_;
  GlTargets targets_;
  int threads_;
  std::map<std::string, GlProgramId> programs_;                     // by "vertex|fragment"
  std::map<std::shared_ptr<const TriangleMesh>, GlMeshId> meshes_;  // owns: pointers stay unique
  GLuint live_mask_ = 0;
  GLuint live_pixels_ = 0, live_slots_ = 0;  // packed rounds' slot -> pixel and pixel -> slot
  int packed_rows_ = 0;
  bool live_mask_full_ = false;  // every pixel live, at live_mask_size_
  glm::ivec2 live_mask_size_{0};
};

}  // namespace sdfreel
