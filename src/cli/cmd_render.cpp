// `sdfreel render`: frames, manifest, framemd5 and video of a timeline.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>

#include "cli/commands_impl.h"
#include "cli/output_folder.h"
#include "cli/progress.h"
#include "io/atomic_file.h"
#include "io/frame_files.h"
#include "io/video_encoder.h"

namespace sdfreel {

namespace fs = std::filesystem;

int run_render(const RenderOptions& o) {
  Timeline tl = load_with_overrides(o);
  const std::vector<int> frames = selected_frames(tl, o);
  const bool whole = int(frames.size()) == tl.frame_count();
  const bool want_video = !tl.video.empty() && whole;
  // Everything that can fail on bad input or a missing backend happens before the first write.
  FramePipeline pipe(tl, make_backend(o.backend, o.threads));
  const ManifestHeader header = manifest_header(tl, pipe.backend());
  const std::string& dir = tl.out_dir;

  fs::create_directories(dir + "/frames");
  // A killed render may have left a half-written temporary: never a frame, but litter.
  remove_stale_temp_files(dir + "/frames");
  remove_stale_temp_files(dir);
  std::optional<Manifest> previous;
  if (o.resume) {
    previous = read_manifest(dir + "/manifest.json");
    if (previous && !previous->header.same_render_as(header)) {
      std::fprintf(stderr, "note: %s/manifest.json is from other settings; rendering every frame\n",
                   dir.c_str());
      previous.reset();
    }
  }
  init_manifest(dir, header);
  if (!tl.video.empty() && !whole)
    std::fprintf(stderr,
                 "note: a partial frame range writes no video; run `sdfreel encode %s -o VIDEO` "
                 "once every frame is rendered\n",
                 dir.c_str());

  std::unique_ptr<VideoEncoder> encoder;
  if (want_video)
    encoder = std::make_unique<VideoEncoder>(
        VideoSettings{dir + "/" + tl.video, tl.codec, tl.width, tl.height, tl.fps, tl.crf});

  Progress progress(int(frames.size()));
  for (int i : frames) {
    if (previous) {
      auto it = previous->frames.find(i);
      if (it != previous->frames.end()) {
        if (auto shown = load_checked_frame(dir, header, it->second, pipe.display())) {
          record_frame(dir, header, it->second);
          if (encoder) encoder->add_frame(*shown);
          progress.frame_done(i, 0.0, true);
          continue;
        }
      }
    }
    RenderedFrame f = pipe.render(i);
    if (tl.write_exr) write_exr_atomic(frame_path(dir, i, "exr"), f.linear, frame_metadata(tl, f));
    if (tl.write_png) write_png16_atomic(frame_path(dir, i, "png"), f.display);
    const double pixels = double(tl.width) * tl.height;
    record_frame(dir, header,
                 ManifestFrame{i, f.ctx.video_time, f.ctx.scene_time, f.linear_hash, f.display_md5,
                               f.seconds, double(f.stats.sdf_evals) / pixels});
    if (encoder) encoder->add_frame(f.display);
    progress.frame_done(i, f.seconds);
  }
  progress.finish();
  if (encoder) {
    encoder->finish();
    std::fprintf(stderr, "wrote %s/%s\n", dir.c_str(), tl.video.c_str());
  }
  return 0;
}

void add_render_command(CLI::App& app, int& status) {
  auto o = std::make_shared<RenderOptions>();
  CLI::App* cmd = app.add_subcommand("render", "render a timeline's frames, hashes and video");
  add_render_options(cmd, *o);
  cmd->callback([o, &status] { status = run_render(*o); });
}

}  // namespace sdfreel
