#pragma once
// Options shared by `render` and `verify`, which override the timeline, and the job they define.
#include <memory>
#include <string>
#include <vector>

#include "backends/gl/gl_choice.h"
#include "render/backend.h"
#include "timeline/timeline.h"

namespace CLI {
class App;
}

namespace sdfreel {

struct RenderOptions {
  std::string timeline_path;
  std::string backend;  // "" : cpu, or gl for a user's shader (backend_for)
  GlChoice gl;          // --gl-platform, --gl-device
  std::string frames, shard, resolution, quality, out;
  int threads = 0;
  int samples = 0;
  bool no_video = false;
  bool resume = false;
  bool preview = false;    // --preview: quarter size, 1 sample, draft, into <dir>-preview
  double scale = 0.0;      // --scale: both sides times this (0: as the timeline says)
  std::string fps;         // --fps: "N" or "N/D", overrides [video] fps
  double duration = 0.0;   // --duration: seconds, overrides [video] duration (0: as it says)
  std::string time_range;  // --time-range A-B: the frames in those seconds, instead of --frames
  std::string video;       // --video NAME: instead of [output] video; a partial range gets one too
};

// The timeline and how its frames are rendered: backend, frames, shard, threads, resolution,
// samples, quality, out, preview and scale (render, verify, check).
void add_frame_options(CLI::App* cmd, RenderOptions& o);
// --no-video and --video (render, check: verify makes no video).
void add_no_video_option(CLI::App* cmd, RenderOptions& o);
// add_frame_options, --no-video and --resume.
void add_render_options(CLI::App* cmd, RenderOptions& o);
// --backend, --gl-platform, --gl-device.
void add_backend_options(CLI::App* cmd, RenderOptions& o);
std::vector<std::string> backend_names();  // cpu gl egl osmesa

// Loads and validates the timeline, then applies the overrides (re-validated). Throws InputError
// or UsageError: nothing has been written yet.
Timeline load_with_overrides(const RenderOptions& o);
// The backend --backend names, or the timeline's default: gl for a user's shader (it has no CPU
// twin; --backend cpu is a UsageError for it), cpu for a built-in scene.
std::string backend_for(const Timeline& tl, const std::string& asked);
// Whether this run, rendering `selected` frames (selected_frames), writes a video: the timeline
// (or --video) names one and every frame is rendered, or --video asks for one of a part.
bool makes_video(const Timeline& tl, const RenderOptions& o, size_t selected);
// The frames to render: --frames and --shard applied to the timeline's frame range.
std::vector<int> selected_frames(const Timeline& tl, const RenderOptions& o);
// A backend by name (egl and osmesa: the GL backend on that platform); UsageError for unknown
// names, RenderError when it cannot start.
std::unique_ptr<Backend> make_backend(const std::string& name, int threads, GlChoice gl = {});
// The backend a command renders `tl` on: backend_for's choice with --threads and the GL options.
std::unique_ptr<Backend> timeline_backend(const Timeline& tl, const RenderOptions& o);

}  // namespace sdfreel
