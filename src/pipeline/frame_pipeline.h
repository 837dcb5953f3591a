#pragma once
// One frame from timeline to pixels and hashes: frame context, backend render, NaN check, half
// rounding, display transform, hashes. Shared by render, still, verify and bench.
#include <memory>
#include <string>

#include "io/color.h"
#include "render/backend.h"
#include "render/compositing_passes.h"
#include "scenes/scene.h"
#include "timeline/timeline.h"

namespace sdfreel {

struct RenderedFrame {
  int index = 0;
  FrameContext ctx;
  ImageRGBA linear;  // half-rounded
  ImageRGB16 display;
  std::string linear_hash, display_md5;
  SampleCounts sample_counts;     // the samples each pixel took
  std::vector<PassImage> passes;  // [output] passes, for the EXR frame; never hashed
  RayStats stats;
  double seconds = 0.0;
};

// FrameContext of frame i: times, camera and every parameter sampled at t_i.
FrameContext frame_context(const Timeline& tl, const SceneInfo& scene, int frame);
// Same, at an arbitrary video time (for `still --time`).
FrameContext frame_context_at(const Timeline& tl, const SceneInfo& scene, int frame, double t);

// The scene a timeline renders: its user's shader, or the built-in scene it names (nullptr when
// there is none of that name).
const SceneInfo* timeline_scene(const Timeline& tl);

class FramePipeline {
 public:
  FramePipeline(const Timeline& tl, std::unique_ptr<Backend> backend);
  // Stays where it was made: the backend's frame source (replays of a shader's buffers) calls it.
  FramePipeline(const FramePipeline&) = delete;
  FramePipeline& operator=(const FramePipeline&) = delete;
  // Throws RenderError when the image has a NaN/Inf (naming frame and pixel).
  RenderedFrame render(int frame);
  RenderedFrame render_context(const FrameContext& ctx);
  const SceneInfo& scene() const { return *scene_; }
  Backend& backend() { return *backend_; }
  const DisplayTransform& display() const { return display_; }
  const Timeline& timeline() const { return tl_; }

 private:
  const Timeline& tl_;
  const SceneInfo* scene_;
  std::unique_ptr<Backend> backend_;
  DisplayTransform display_;
};

// EXR metadata for a rendered frame.
std::map<std::string, std::string> frame_metadata(const Timeline& tl, const RenderedFrame& f);

}  // namespace sdfreel
