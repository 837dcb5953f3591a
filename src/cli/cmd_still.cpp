// `sdfreel still TIMELINE --time SECONDS -o FILE`: one frame at any video time.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <filesystem>

#include "cli/commands_impl.h"
#include "cli/output_checks.h"
#include "io/frame_files.h"
#include "io/frame_formats.h"
#include "io/sample_count_images.h"
#include "timeline/rules.h"

namespace sdfreel {

namespace {

struct StillOptions {
  RenderOptions render;
  double time = 0.0;
  bool has_time = false;
  std::string frames;  // a mistake: still takes a time, render takes frames
  std::string output;
  std::string sample_counts;  // "" = none; .exr exact counts, .png heat map
};

// The extension of -o's file (lower case, no dot), which names its format: exr and png as
// always, any other OpenImageIO writes, found before the frame is rendered.
std::string still_extension(const std::string& output) {
  std::string ext = lower_extension(output);
  if (ext.size() < 2)
    throw UsageError("-o " + output +
                     ": name the file with the extension of its format (.exr, .png, .tif, .dpx, "
                     ".jpg, ...)");
  ext.erase(0, 1);
  if (ext == "exr" || ext == "png") return ext;
  if (std::string problem = unwritable_frame_format(ext); !problem.empty())
    throw UsageError("-o " + output + ": " + problem +
                     "; use .exr, .png, .tif, .dpx, .jpg or another format it writes");
  return ext;
}

int run_still(const StillOptions& o) {
  if (!o.frames.empty())
    throw UsageError(
        "still renders one frame at a video time: --time SECONDS (frame N is at N / "
        "fps seconds); for frames by number use `sdfreel render TIMELINE --frames " +
        o.frames + "`");
  if (!o.has_time)
    throw UsageError("--time SECONDS is required: the video time of the frame to render");
  const std::string ext = still_extension(o.output);
  const std::string counts_ext = std::filesystem::path(o.sample_counts).extension().string();
  if (!o.sample_counts.empty() && counts_ext != ".exr" && counts_ext != ".png")
    throw UsageError("--sample-counts " + o.sample_counts + ": the file must end in .exr or .png");
  if (!std::isfinite(o.time) || o.time < 0.0)
    throw UsageError("--time must be a finite number of seconds >= 0");
  RenderOptions ro = o.render;
  ro.no_video = true;  // a still has no video, so h264's even-size rule does not apply
  Timeline tl = load_with_overrides(ro);
  FramePipeline pipe(tl, timeline_backend(tl, o.render));
  const int frame = int(std::llround(o.time * tl.fps.value()));
  RenderedFrame f = pipe.render_context(frame_context_at(tl, pipe.scene(), frame, o.time));
  write_frame_file(o.output, frame_format(ext, tl.frame_options), f.linear, f.display,
                   frame_metadata(tl, f), f.passes);
  if (!o.sample_counts.empty()) {
    const SampleCounts& counts = f.sample_counts;
    if (counts_ext == ".exr")
      write_exr_atomic(o.sample_counts, sample_count_image(counts, tl.width, tl.height),
                       frame_metadata(tl, f));
    else
      write_png16_atomic(o.sample_counts, sample_heat_map(counts, tl.width, tl.height,
                                                          int(f.ctx.sample_offsets.size())));
    double mean = 0.0;
    for (uint16_t n : counts) mean += n;
    std::fprintf(stderr, "wrote %s (%.2f samples a pixel on average)\n", o.sample_counts.c_str(),
                 mean / double(std::max<size_t>(counts.size(), 1)));
  }
  std::fprintf(stderr, "wrote %s (TIME %.6g) in %.2f s\n", o.output.c_str(), f.ctx.scene_time,
               f.seconds);
  return 0;
}

}  // namespace

void add_still_command(CLI::App& app, int& status) {
  auto o = std::make_shared<StillOptions>();
  CLI::App* cmd = app.add_subcommand("still", "render one frame at a video time to an image file");
  cmd->add_option("TIMELINE", o->render.timeline_path, "timeline file (TOML)")->required();
  CLI::Option* time = cmd->add_option("--time", o->time, "video time in seconds (required)");
  // Accepted only to answer the mistake with what to use instead (not in --help).
  cmd->add_option("--frames", o->frames)->group("");
  cmd->add_option("-o,--output", o->output,
                  "output file: .exr (linear), .png (display) or another format by its extension "
                  "(.tif, .dpx, .jpg, ...)")
      ->required();
  add_backend_options(cmd, o->render);
  cmd->add_option("--threads", o->render.threads, "worker threads (default: all cores)")
      ->check(CLI::Range(1, 1024));
  cmd->add_option("--resolution", o->render.resolution, "WxH, overrides the timeline");
  cmd->add_option("--sample-counts", o->sample_counts,
                  "also write the samples each pixel took: .exr (exact, every channel) or .png "
                  "(heat map, log scale up to the maximum)");
  cmd->add_option("--samples", o->render.samples, "samples per pixel")->check(CLI::Range(1, 1024));
  cmd->add_option("--quality", o->render.quality, "draft | final | reference")
      ->check(CLI::IsMember({"draft", "final", "reference"}));
  cmd->callback([o, time, &status] {
    o->has_time = time->count() > 0;
    status = run_still(*o);
  });
}

}  // namespace sdfreel
