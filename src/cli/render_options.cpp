#include "cli/render_options.h"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "backends/cpu/cpu_backend.h"
#ifdef SDFREEL_HAVE_GL
#include "backends/gl/gl_backend.h"
#endif
#include "cli/frame_range.h"
#include "cli/option_numbers.h"
#include "cli/time_overrides.h"
#include "cli/video_choice.h"
#include "io/color.h"
#include "pipeline/errors.h"
#include "scenes/registry.h"
#include "shader/shader_timeline.h"
#include "timeline/rules.h"

namespace sdfreel {

namespace {

struct OcioChecker : ColorChecker {
  std::string check(const std::string& config, const std::string& display,
                    const std::string& view) const override {
    try {
      DisplayTransform t(config, display, view);
      return "";
    } catch (const std::exception& e) {
      return e.what();
    }
  }
};

// --preview and --scale. A side scales to the nearest even number (h264's rule), at least 2.
void apply_preview(const RenderOptions& o, Timeline& tl) {
  const double scale = o.scale > 0.0 ? o.scale : o.preview ? 0.25 : 1.0;
  if (scale != 1.0) {
    auto side = [&](int n) { return std::max(2, 2 * int(std::lround(n * scale / 2.0))); };
    tl.width = side(tl.width);
    tl.height = side(tl.height);
    tl.resolution_line = tl.resolution_column = 0;  // no longer the file's size
  }
  if (!o.preview) return;
  tl.samples = 1;
  tl.adaptive.enabled = false;
  tl.quality = Quality::Draft;
  tl.out_dir += "-preview";  // never over the real render's frames (--out still names the folder)
}

// --video NAME: a file name in the output folder, its codec the container's.
void apply_video_option(const RenderOptions& o, Timeline& tl) {
  if (o.no_video) throw UsageError("--video and --no-video: give one of them");
  if (o.video.find('/') != std::string::npos)
    throw UsageError("--video " + o.video +
                     ": a file name in the output folder (--out names the folder)");
  tl.codec = codec_of_output(o.video, tl.codec, "--video");
  if (std::string problem = check_video_name(o.video, tl.codec); !problem.empty())
    throw UsageError("--video: " + problem);
  tl.video = o.video;
}

}  // namespace

bool makes_video(const Timeline& tl, const RenderOptions& o, size_t selected) {
  // A part of the frames gets a video only when --video asks (else `sdfreel encode` later).
  return !tl.video.empty() && (!o.video.empty() || selected == size_t(tl.frame_count()));
}

void add_render_options(CLI::App* cmd, RenderOptions& o) {
  add_frame_options(cmd, o);
  add_no_video_option(cmd, o);
  cmd->add_flag("--resume", o.resume,
                "keep frames on disk whose hashes match the manifest, render the rest");
}

void add_frame_options(CLI::App* cmd, RenderOptions& o) {
  cmd->add_option("TIMELINE", o.timeline_path, "timeline file (TOML)")->required();
  add_backend_options(cmd, o);
  cmd->add_option("--frames", o.frames, "frames to render, e.g. 0-99 or 1,5,9-12 (inclusive)");
  cmd->add_option("--shard", o.shard,
                  "I/N: the I-th (0-based) of N contiguous parts of the frames");
  cmd->add_option("--threads", o.threads, "worker threads (default: all cores)")
      ->check(CLI::Range(1, 1024));
  cmd->add_option("--resolution", o.resolution, "WxH, overrides the timeline");
  cmd->add_option("--samples", o.samples, "samples per pixel, 1..1024")->check(CLI::Range(1, 1024));
  cmd->add_option("--quality", o.quality, "draft | final | reference")
      ->check(CLI::IsMember({"draft", "final", "reference"}));
  cmd->add_option("--out", o.out, "output folder, overrides [output] dir");
  cmd->add_flag("--preview", o.preview,
                "a quick look at the whole timeline: --scale 0.25, 1 sample, draft quality, into "
                "the output folder's name + -preview (other options still override)");
  cmd->add_option("--scale", o.scale, "both sides of the picture times this, e.g. 0.5")
      ->check(CLI::Range(0.001, 16.0));
  cmd->add_option("--fps", o.fps, "frames per second, N or N/D, overrides [video] fps");
  cmd->add_option("--duration", o.duration, "seconds of video, overrides [video] duration");
  cmd->add_option("--time-range", o.time_range,
                  "A-B: the frames whose video time lies in A..B seconds (inclusive), instead of "
                  "--frames");
}

void add_no_video_option(CLI::App* cmd, RenderOptions& o) {
  cmd->add_flag("--no-video", o.no_video, "write frames and hashes but no video");
  cmd->add_option("--video", o.video,
                  "NAME: the video's file in the output folder instead of [output] video, its "
                  "codec from the container; with --frames, --time-range or --shard, a video of "
                  "just those frames");
}

Timeline load_with_overrides(const RenderOptions& o) {
  OcioChecker checker;
  ShaderTimelineLoader shaders;
  Timeline tl = load_timeline(all_scenes(), o.timeline_path, &checker, &shaders);
  backend_for(tl, o.backend);  // refuses --backend cpu for a shader before anything is written
  apply_preview(o, tl);        // first, so that the options below override it
  apply_time_overrides(o.fps, o.duration, tl);
  if (!o.resolution.empty()) {
    const Resolution r = parse_resolution_option(o.resolution);
    if (std::string problem = check_resolution(r.width, r.height); !problem.empty())
      throw InputError(tl.path, 0, 0, "--resolution: " + problem);
    tl.width = int(r.width);
    tl.height = int(r.height);
    tl.resolution_line = tl.resolution_column = 0;
  }
  if (o.samples) {
    tl.samples = o.samples;
    tl.adaptive.enabled = false;  // --samples asks for fixed sampling
  }
  if (!o.quality.empty()) tl.quality = *parse_quality(o.quality);
  if (!o.out.empty()) tl.out_dir = o.out;
  if (!o.video.empty()) apply_video_option(o, tl);
  if (o.no_video) tl.video.clear();
  validate_overrides(tl, makes_video(tl, o, selected_frames(tl, o).size()));
  return tl;
}

std::string backend_for(const Timeline& tl, const std::string& asked) {
  if (!tl.shader_scene) return asked.empty() ? "cpu" : asked;
  if (asked == "cpu")
    throw UsageError("--backend cpu: " + tl.path +
                     " renders a user's shader, which runs on the GL backend only (--backend gl, "
                     "egl or osmesa)");
  return asked.empty() ? "gl" : asked;
}

std::unique_ptr<Backend> timeline_backend(const Timeline& tl, const RenderOptions& o) {
  return make_backend(backend_for(tl, o.backend), o.threads, o.gl);
}

std::vector<int> selected_frames(const Timeline& tl, const RenderOptions& o) {
  std::vector<int> frames;
  if (!o.frames.empty() && !o.time_range.empty())
    throw UsageError("--frames and --time-range both select frames: give one of them");
  if (!o.time_range.empty()) {
    frames = frames_in_time_range(o.time_range, tl);
  } else if (o.frames.empty()) {
    for (int i = 0; i < tl.frame_count(); ++i) frames.push_back(i);
  } else {
    frames = parse_frame_list(o.frames, tl.frame_count());
  }
  if (!o.shard.empty()) frames = shard_of(frames, o.shard);
  return frames;
}

void add_backend_options(CLI::App* cmd, RenderOptions& o) {
  cmd->add_option(
         "--backend", o.backend,
         "cpu | gl (EGL, else OSMesa) | egl | osmesa (default cpu; gl for a user's shader)")
      ->check(CLI::IsMember(backend_names()));
  cmd->add_option("--gl-platform", o.gl.platform,
                  "egl | osmesa | auto, for --backend gl (env SDFREEL_GL_PLATFORM; default auto)")
      ->check(CLI::IsMember({"egl", "osmesa", "auto"}));
  cmd->add_option("--gl-device", o.gl.device,
                  "software | gpu | N from `sdfreel devices` (env SDFREEL_GL_DEVICE; default "
                  "software, Mesa's llvmpipe)");
}

std::vector<std::string> backend_names() {
  return {"cpu", "gl", "egl", "osmesa"};
}

std::unique_ptr<Backend> make_backend(const std::string& name, int threads, GlChoice gl) {
  if (name == "cpu") return std::make_unique<CpuBackend>(threads);
  if (name == "gl" || name == "egl" || name == "osmesa") {
    if (name != "gl") gl.platform = name;
    gl.threads = threads;
#ifdef SDFREEL_HAVE_GL
    // llvmpipe reads its thread count when the first context is created; an explicit
    // LP_NUM_THREADS in the environment wins over --threads.
    if (threads > 0) setenv("LP_NUM_THREADS", std::to_string(threads).c_str(), 0);
    try {
      return std::make_unique<GlBackend>(gl);
    } catch (const std::exception& e) {
      throw RenderError("cannot start the " + name + " backend: " + e.what());
    }
#else
    throw RenderError("the GL backend is not built into this sdfreel (no EGL or GL headers)");
#endif
  }
  throw UsageError("unknown backend '" + name + "' (cpu | gl | egl | osmesa)");
}

}  // namespace sdfreel
