// `sdfreel check TIMELINE`: everything `render` checks before it writes, and what it would make,
// without rendering or writing anything (exit 0, or 2 with the same message as render).
#include <CLI/CLI.hpp>
#include <cstdio>

#include "cli/camera_clearance.h"
#include "cli/camera_path_stats.h"
#include "cli/commands_impl.h"
#include "cli/output_checks.h"
#include "cli/output_folder.h"
#include "cli/soundtrack.h"
#include "io/frame_formats.h"
#include "pipeline/frame_memory.h"
#include "render/adaptive_sampling.h"
#include "render/quality.h"
#include "scenes/registry.h"
#include "shader/shader_project.h"
#include "timeline/video_codec_rules.h"

namespace sdfreel {

namespace {

void print_camera(const Timeline& tl, const SceneInfo& scene) {
  const size_t keys = tl.camera.keys.size();
  if (keys == 0) {
    std::printf("camera:     the scene's default, still\n");
    return;
  }
  const CameraPathStats s = camera_path_stats(tl, scene.default_camera);
  std::printf(
      "camera:     %zu key%s, %s interpolation%s; path %.2f units, top speed %.2f units/s "
      "at t = %.2f s\n",
      keys, keys == 1 ? "" : "s", interp_name(tl.camera.interp),
      tl.camera.constant_speed ? " at constant speed" : "", s.length, s.top_speed, s.top_speed_at);
}

// Warns (exit 0) where the eye of a frame is inside the scene's solids or cuts a surface open.
void print_clearance(const Timeline& tl, const SceneInfo& scene, const std::vector<int>& frames) {
  const CameraClearance c = camera_clearance(tl, scene, frames);
  const double fps = tl.fps.value();
  if (!c.scene_can_tell) {
    std::printf("geometry:   not checked (%s cannot tell where its solids are)\n",
                tl.shader_scene ? "a user's shader" : tl.scene.c_str());
  } else if (c.inside.empty() && c.too_near.empty()) {
    std::printf("geometry:   the camera stays clear of the scene's surfaces (%zu frames checked)\n",
                frames.size());
  } else {
    if (!c.inside.empty())
      std::printf(
          "warning:    the camera is inside the scene's geometry at %s: those frames show "
          "a surface from within; move the camera keys near these times\n",
          frame_runs(c.inside, fps).c_str());
    if (!c.too_near.empty())
      std::printf(
          "warning:    the camera comes within the near plane (%.2f units) of a surface at "
          "%s: the surface is cut open there\n",
          c.near_plane, frame_runs(c.too_near, fps).c_str());
  }
}

void print_output(const Timeline& tl, const RenderOptions& o, const std::vector<int>& frames) {
  std::string files;
  for (const std::string& ext : timeline_frame_files(tl)) files += "frames/NNNNN." + ext + ", ";
  std::printf("output:     %s/ (%sframes.framemd5, manifest.json)\n", tl.out_dir.c_str(),
              files.c_str());
  if (tl.video.empty())
    std::printf("video:      none\n");
  else if (!makes_video(tl, o, frames.size()))
    std::printf(
        "video:      none: a partial frame range writes no video (then `sdfreel encode`, or "
        "--video NAME)\n");
  else if (find_video_codec_rule(tl.codec)->takes_crf)
    std::printf("video:      %s/%s (%s, crf %d)\n", tl.out_dir.c_str(), tl.video.c_str(),
                tl.codec.c_str(), tl.crf);
  else
    std::printf("video:      %s/%s (%s)\n", tl.out_dir.c_str(), tl.video.c_str(), tl.codec.c_str());
  if (!tl.audio.path.empty()) {
    char fade[64] = "";
    if (tl.audio.fade > 0)
      std::snprintf(fade, sizeof fade, ", fading out over the last %.6g s", tl.audio.fade);
    std::string codec = soundtrack_encoder_for(tl.video);
    if (codec.empty()) codec = "nothing: this container holds no sound";
    std::printf("audio:      %s from %.6g s%s, as %s\n", tl.audio.path.c_str(), tl.audio.offset,
                fade, tl.video.empty() ? "nothing yet (no video)" : codec.c_str());
  }
}

int run_check(const RenderOptions& o) {
  const Timeline tl = load_with_overrides(o);
  validate_frame_formats(tl);
  check_output_folder(tl.out_dir);
  check_frame_memory(tl);  // render's pipeline checks it; check makes none for a built-in scene
  const std::vector<int> frames = selected_frames(tl, o);
  validate_video_encoder(tl, makes_video(tl, o, frames.size()));
  check_soundtrack(tl);
  const SceneInfo* scene = timeline_scene(tl);
  if (!scene) throw UsageError("unknown scene '" + tl.scene + "'");
  if (tl.shader_scene) {
    // The shader is compiled as render would (a compile error exits 2 here too); nothing runs.
    FramePipeline pipe(tl, timeline_backend(tl, o));
    std::printf("shader:     %s (%zu pass%s, compiled on %s)\n", tl.shader.c_str(),
                scene->shader_project->passes.size(),
                scene->shader_project->passes.size() == 1 ? "" : "es",
                pipe.backend().name().c_str());
  } else {
    std::printf("scene:      %s\n", tl.scene.c_str());
  }
  std::printf("frames:     %d at %lld/%lld fps (%.3f s); this run renders %zu (%d-%d)\n",
              tl.frame_count(), (long long)tl.fps.num, (long long)tl.fps.den, tl.duration,
              frames.size(), frames.empty() ? 0 : frames.front(),
              frames.empty() ? 0 : frames.back());
  std::printf("picture:    %dx%d, %s, quality %s\n", tl.width, tl.height,
              tl.adaptive.enabled ? ("adaptive " + adaptive_text(tl.adaptive_at_size())).c_str()
                                  : (std::to_string(tl.samples) +
                                     (tl.samples == 1 ? " sample" : " samples") + " a pixel")
                                        .c_str(),
              quality_name(tl.quality));
  print_camera(tl, *scene);
  print_clearance(tl, *scene, frames);
  print_output(tl, o, frames);
  std::printf("%s: ok, nothing written\n", tl.path.c_str());
  return 0;
}

}  // namespace

void add_check_command(CLI::App& app, int& status) {
  auto o = std::make_shared<RenderOptions>();
  CLI::App* cmd = app.add_subcommand(
      "check", "validate a timeline as render would and print what it would make; writes nothing");
  add_frame_options(cmd, *o);
  add_no_video_option(cmd, *o);
  cmd->callback([o, &status] { status = run_check(*o); });
}

}  // namespace sdfreel
