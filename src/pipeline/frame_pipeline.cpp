#include "pipeline/frame_pipeline.h"

#include <tbb/parallel_invoke.h>

#include <chrono>
#include <cstdio>

#include "io/display_referred.h"
#include "io/half_image.h"
#include "io/hashing.h"
#include "pipeline/errors.h"
#include "pipeline/frame_memory.h"
#include "pipeline/pass_images.h"
#include "scenes/registry.h"
#include "shader/shader_project.h"

namespace sdfreel {

FrameContext frame_context_at(const Timeline& tl, const SceneInfo& scene, int frame, double t) {
  FrameContext ctx;
  ctx.frame_index = frame;
  ctx.video_time = t;
  ctx.fps = tl.fps.value();
  ctx.scene_time = tl.time ? tl.time->sample(t).at(0) : t;
  ctx.width = tl.width;
  ctx.height = tl.height;
  ctx.samples = tl.samples;
  ctx.adaptive = tl.adaptive_at_size();
  ctx.seed = tl.seed;
  ctx.quality = tl.quality;
  ctx.pose = tl.camera.sample(t, scene.default_camera);
  ctx.params = ParamValues(&scene.params);
  for (const ParamTrack& p : tl.params) ctx.params.set(p.name, p.curve.sample(t));
  finish_frame_context(ctx);
  return ctx;
}

FrameContext frame_context(const Timeline& tl, const SceneInfo& scene, int frame) {
  return frame_context_at(tl, scene, frame, tl.video_time(frame));
}

const SceneInfo* timeline_scene(const Timeline& tl) {
  return tl.shader_scene ? tl.shader_scene.get() : find_scene(tl.scene);
}

FramePipeline::FramePipeline(const Timeline& tl, std::unique_ptr<Backend> backend)
    : tl_(tl),
      scene_(timeline_scene(tl)),
      backend_(std::move(backend)),
      display_(tl.color_config, tl.display, tl.view) {
  if (!scene_) throw UsageError("unknown scene '" + tl.scene + "'");
  check_frame_memory(tl);  // before the backend allocates anything of the frame's size
  // Before begin: a shader with feedback replays earlier frames while it starts.
  backend_->set_frame_source([this](int i) { return frame_context(tl_, *scene_, i); });
  record_passes(tl.frame_options.passes, *backend_);
  backend_->begin(*scene_);
}

RenderedFrame FramePipeline::render(int frame) {
  return render_context(frame_context(tl_, *scene_, frame));
}

RenderedFrame FramePipeline::render_context(const FrameContext& ctx) {
  RenderedFrame f;
  f.index = ctx.frame_index;
  f.ctx = ctx;
  const auto start = std::chrono::steady_clock::now();
  f.linear = backend_->render(ctx, f.stats);
  f.sample_counts = backend_->sample_counts();  // before passes that render again
  f.passes = pass_images(tl_.frame_options.passes, *backend_, ctx);
  // Shadertoy code often divides by zero: shown black, as on the site, unless asked otherwise.
  if (scene_->shader_project && scene_->shader_project->non_finite_black) {
    std::string first;
    if (size_t n = zero_non_finite(f.linear, &first))
      std::fprintf(stderr,
                   "sdfreel: warning: frame %d: %zu NaN or infinite values written as 0 "
                   "(the first: %s)\n",
                   ctx.frame_index, n, first.c_str());
  }
  if (auto bad = find_non_finite(f.linear))
    throw RenderError("frame " + std::to_string(ctx.frame_index) + ": " + *bad +
                      " (a frame with NaN or Inf is never written)");
  if (scene_->display_referred) {  // the backend's numbers are the display's (docs/shaders.md)
    f.display = quantised_display(f.linear);
    f.linear = srgb_decoded(f.linear);
    round_to_half(f.linear);
  } else {
    round_to_half(f.linear);
    f.display = display_.apply(f.linear);
  }
  f.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  // Each hash reads its own image: both at once (a still, or a run's last frame, waits on them).
  tbb::parallel_invoke([&] { f.linear_hash = linear_half_hash(f.linear); },
                       [&] { f.display_md5 = md5_rgb48le(f.display); });
  return f;
}

std::map<std::string, std::string> frame_metadata(const Timeline& tl, const RenderedFrame& f) {
  char buf[512];
  const CameraPose& p = f.ctx.pose;
  std::snprintf(buf, sizeof buf,
                "position=[%.9g, %.9g, %.9g] target=[%.9g, %.9g, %.9g] fov=%.9g roll=%.9g",
                p.position.x, p.position.y, p.position.z, p.target.x, p.target.y, p.target.z,
                p.fov_deg, p.roll_deg);
  auto num = [](double v) {
    char b[64];
    std::snprintf(b, sizeof b, "%.17g", v);
    return std::string(b);
  };
  return {{"timeline_sha256", tl.sha256},     {"scene", tl.scene},
          {"frame", std::to_string(f.index)}, {"video_time", num(f.ctx.video_time)},
          {"TIME", num(f.ctx.scene_time)},    {"camera", buf},
          {"linear_md5", f.linear_hash},      {"display_md5", f.display_md5}};
}

}  // namespace sdfreel
