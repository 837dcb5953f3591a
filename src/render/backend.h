#pragma once
// A backend turns (scene, frame context) into the linear image of that frame. Everything after
// that (display transform, files, hashes, video) is shared and backend-agnostic.
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "render/buffer_checkpoints.h"
#include "render/frame_context.h"
#include "render/image.h"
#include "render/live_pixels.h"

namespace sdfreel {

struct SceneInfo;
struct RayStats;

class Backend {
 public:
  virtual ~Backend() = default;
  virtual std::string name() const = 0;
  // Library versions and renderer strings that shape pixels, for manifest.json.
  virtual std::map<std::string, std::string> versions() const = 0;
  // Once per render, before any frame: build the scene (CPU) or compile its shaders (GL).
  virtual void begin(const SceneInfo& scene) = 0;
  // The linear RGBA image of one frame. Deterministic: depends on ctx only.
  virtual ImageRGBA render(const FrameContext& ctx, RayStats& stats) = 0;
  // Samples each pixel of the last rendered frame took (all the same unless adaptive).
  virtual const SampleCounts& sample_counts() const = 0;
  // For the sdf_evals compositing pass (render/compositing_passes.h), asked for before begin():
  // the SDF evaluations each pixel of the last frame took, all its samples together (row-major,
  // top row first). Empty from a backend that does not count them (a user's shader).
  virtual void record_sdf_evals(bool on) { (void)on; }
  virtual const std::vector<float>& sdf_eval_counts() const {
    static const std::vector<float> none;
    return none;
  }
  // The context of any frame of the render: a user's shader with feedback replays its buffers
  // through it (docs/shaders.md). Backends without such state ignore it.
  virtual void set_frame_source(std::function<FrameContext(int)> source) { (void)source; }
  // Where such a shader keeps checkpoints of its buffers and restarts from (docs/shaders.md).
  virtual void set_checkpoints(std::shared_ptr<BufferCheckpoints> checkpoints) {
    (void)checkpoints;
  }
};

}  // namespace sdfreel
