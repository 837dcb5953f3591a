// `sdfreel render`: frames, manifest, framemd5 and video of a timeline.
#include <tbb/parallel_for_each.h>

#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>

#include "cli/commands_impl.h"
#include "cli/interrupt_guard.h"
#include "cli/output_checks.h"
#include "cli/output_folder.h"
#include "cli/progress.h"
#include "cli/soundtrack.h"
#include "io/atomic_file.h"
#include "io/folder_claim.h"
#include "io/frame_formats.h"
#include "io/manifest_journal.h"
#include "io/video_encoder.h"
#include "pipeline/frame_writer.h"
#include "pipeline/shader_checkpoints.h"

namespace sdfreel {

namespace fs = std::filesystem;

namespace {

// Frame files first, then the journal entry that lists them, then the video: a frame is listed
// only once its files are complete on disk. Any failure (a full disk) names the frame, exit 1.
void publish_frame(const std::string& dir, const Timeline& tl, const ManifestHeader& header,
                   const RenderedFrame& f, VideoEncoder* encoder) {
  const int i = f.index;
  try {
    const std::map<std::string, std::string> metadata = frame_metadata(tl, f);
    // Each file on a thread of its own (an EXR's PIZ and a PNG's deflate run on one thread
    // each): the last frame of a run, which no render overlaps, takes the time of the slower.
    tbb::parallel_for_each(
        header.frame_files.begin(), header.frame_files.end(), [&](const std::string& ext) {
          write_frame_file(frame_path(dir, i, ext), frame_format(ext, tl.frame_options), f.linear,
                           f.display, metadata, f.passes);
        });
    const double pixels = double(tl.width) * tl.height;
    record_frame(dir, header,
                 ManifestFrame{i, f.ctx.video_time, f.ctx.scene_time, f.linear_hash, f.display_md5,
                               f.seconds, double(f.stats.sdf_evals) / pixels});
    if (encoder) encoder->add_frame(f.display);
  } catch (const std::exception& e) {
    throw RenderError("frame " + std::to_string(i) + ": " + e.what());
  }
}

// The render of other settings a folder holds (its manifest's frames and video) goes before this
// one starts: otherwise its frames beyond this range and its video would stay beside the new ones,
// looking current. Called under the folder lock, when no render of it is running.
void remove_foreign_render(const std::string& dir, const Manifest& old) {
  std::error_code ec;
  size_t removed = 0;
  for (const auto& [i, f] : old.frames)
    for (const std::string& ext : old.header.frame_files)
      removed += fs::remove(frame_path(dir, i, ext), ec);
  const std::string& video = old.header.video;
  const bool had_video = !video.empty() && fs::remove(dir + "/" + video, ec);
  fs::remove_all(checkpoint_dir(dir), ec);  // of the old settings: never usable
  std::fprintf(stderr,
               "note: %s held a render of other settings; its %zu frame files%s%s were removed\n",
               dir.c_str(), removed, had_video ? " and " : "", had_video ? video.c_str() : "");
}

}  // namespace

int run_render(const RenderOptions& o) {
  Timeline tl = load_with_overrides(o);
  validate_frame_formats(tl);
  const std::vector<int> frames = selected_frames(tl, o);
  const bool want_video = makes_video(tl, o, frames.size());
  validate_video_encoder(tl, want_video);
  check_soundtrack(tl);
  const auto soundtrack = render_soundtrack(tl, frames, tl.out_dir + "/" + tl.video, want_video);
  // Everything that can fail on bad input or a missing backend happens before the first write.
  FramePipeline pipe(tl, timeline_backend(tl, o));
  const ManifestHeader header = manifest_header(tl, pipe.backend());
  const std::string& dir = tl.out_dir;
  check_output_folder(dir);

  fs::create_directories(dir + "/frames");
  // A killed render may have left half-written temporaries (frames, manifest, video): never
  // published, but litter.
  remove_stale_temp_files(dir + "/frames");
  remove_stale_temp_files(dir);
  FolderClaim claim;
  bool foreign = false;
  std::string damaged;
  const Manifest existing =
      consolidate_manifest(dir, header, &damaged, [&](const Manifest* other_settings) {
        // Under the folder lock: no render can start or claim in between.
        foreign = other_settings != nullptr;
        if (foreign && FolderClaim::others_active(dir))
          throw UsageError(
              dir +
              " is being rendered right now with other settings (timeline, backend, "
              "resolution, samples, quality or colour): refusing to mix the two renders; "
              "use another --out or wait for it to finish");
        claim.acquire(dir);
        if (foreign) remove_foreign_render(dir, *other_settings);
      });
  use_shader_checkpoints(pipe, dir, render_key(header), true);
  if (!damaged.empty())
    std::fprintf(stderr, "note: %s/manifest.json is damaged (%s); it was set aside\n", dir.c_str(),
                 damaged.c_str());
  std::optional<Manifest> previous;
  if (o.resume) {
    if (foreign)
      std::fprintf(stderr, "note: %s/manifest.json is from other settings; rendering every frame\n",
                   dir.c_str());
    else
      previous = existing;  // frames on disk are still checked against their hashes below
  }
  if (!tl.video.empty() && !want_video)
    std::fprintf(stderr,
                 "note: a partial frame range writes no video (unless --video names one); run "
                 "`sdfreel encode %s -o VIDEO` once every frame is rendered\n",
                 dir.c_str());

  std::unique_ptr<VideoEncoder> encoder;
  if (want_video)
    encoder = std::make_unique<VideoEncoder>(VideoSettings{dir + "/" + tl.video, tl.codec, tl.width,
                                                           tl.height, tl.fps, tl.crf, soundtrack});

  if (frames.empty())  // a shard of more parts than frames
    std::fprintf(stderr, "note: --shard %s of %d frames selects none: nothing to render\n",
                 o.shard.c_str(), tl.frame_count());
  const auto start = std::chrono::steady_clock::now();
  int kept = 0;
  Progress progress(int(frames.size()));
  // Files, journal lines, video frames and progress lines go through one writer thread, in frame
  // order, while the next frame renders. Only that thread writes until finish().
  FrameWriter writer;
  InterruptGuard interrupts;
  size_t queued = 0;  // frames handed to the writer, kept or rendered
  try {
    for (int i : frames) {
      if (InterruptGuard::signal_seen()) break;  // the frames queued so far are still written
      ++queued;
      if (previous) {
        auto it = previous->frames.find(i);
        if (it != previous->frames.end()) {
          std::string why;
          if (auto shown = load_checked_frame(dir, header, it->second, pipe.display(), &why)) {
            // Already listed in the manifest consolidated above.
            ++kept;
            writer.push([&progress, enc = encoder.get(), i, shown = std::move(*shown)] {
              if (enc) enc->add_frame(shown);
              progress.frame_done(i, 0.0, true);
            });
            continue;
          }
          std::fprintf(stderr, "note: frame %d is rendered again: %s\n", i, why.c_str());
        }
      }
      auto f = std::make_shared<const RenderedFrame>(pipe.render(i));
      writer.push([&, f] {
        publish_frame(dir, tl, header, *f, encoder.get());
        progress.frame_done(f->index, f->seconds);
      });
    }
    writer.finish();
  } catch (const std::exception&) {
    // A render failure: the frames rendered before it are still written (a write failure has
    // stopped the writer already), and nothing writes while the manifest is consolidated.
    writer.finish_quietly();
    // The frames finished before the failure are listed in manifest.json and frames.framemd5
    // too, not only in the journal (best effort: the disk may be full).
    try {
      consolidate_manifest(dir, header);
    } catch (const std::exception&) {
    }
    throw;
  }
  progress.finish();
  consolidate_manifest(dir, header);
  if (const int signo = InterruptGuard::signal_seen(); signo && queued < frames.size()) {
    encoder.reset();  // a video needs every frame: its temporary file goes
    std::fprintf(stderr,
                 "sdfreel: stopped by %s: %zu of %zu frames are finished in %s and listed in its "
                 "manifest; the same command with --resume renders the other %zu\n",
                 signal_name(signo), queued, frames.size(), dir.c_str(), frames.size() - queued);
    return 128 + signo;
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const char* no_video = tl.video.empty() ? (o.no_video ? "no video (--no-video)" : "no video")
                         : !want_video    ? "no video (a partial frame range)"
                                          : nullptr;
  std::fprintf(
      stderr, "done: %zu frame%s in %s (%zu rendered, %d kept from before) in %.1f s%s%s\n",
      frames.size(), frames.size() == 1 ? "" : "s", dir.c_str(), frames.size() - size_t(kept), kept,
      seconds, no_video ? "; " : "", no_video ? no_video : "");
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
