// `sdfreel map TIMELINE -o map.png`: where the camera goes. The scene rendered by its own renderer
// from above (and, where that shows more than a wall, from the side), each view fitted to the
// camera path, with the path, its keys and the camera's direction drawn over it.
#include <CLI/CLI.hpp>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "cli/commands_impl.h"
#include "cli/quick_look_options.h"
#include "draw/path_map.h"

namespace sdfreel {

namespace {

struct MapOptions {
  RenderOptions render;
  std::string output;
  int width = 960;
  double time = 0.0;  // the scene's state the map shows (video time, seconds)
};

draw::PathPoint path_point(const Timeline& tl, const SceneInfo& scene, double t) {
  const CameraPose pose = tl.camera.sample(t, scene.default_camera);
  return {t, pose.position, glm::dvec3(make_camera_basis(pose).forward)};
}

// The eye at every frame, each key, and the camera at each whole second.
draw::PathMarks path_marks(const Timeline& tl, const SceneInfo& scene) {
  draw::PathMarks m;
  for (int f = 0; f < tl.frame_count(); ++f)
    m.path.push_back(tl.camera.sample(tl.video_time(f), scene.default_camera).position);
  for (const CameraKey& k : tl.camera.keys) m.keys.push_back(path_point(tl, scene, k.t));
  if (tl.camera.keys.empty()) m.keys.push_back(path_point(tl, scene, 0.0));
  for (int s = 1; s < tl.duration; ++s) m.seconds.push_back(path_point(tl, scene, s));
  return m;
}

int run_map(const MapOptions& o) {
  if (std::filesystem::path(o.output).extension() != ".png")
    throw UsageError("-o " + o.output + ": the map is a PNG, the file must end in .png");
  RenderOptions ro = o.render;
  ro.no_video = true;  // nothing is encoded: h264's even-size rule does not apply
  Timeline tl = load_with_overrides(ro);
  if (tl.shader_scene)
    throw UsageError(tl.path +
                     ": a user's shader draws its own picture; there is no scene "
                     "for a map to show");
  if (o.time < 0.0 || o.time > tl.duration)
    throw UsageError("--time " + std::to_string(o.time) + " is outside the timeline (0 to " +
                     std::to_string(tl.duration) + " s)");
  const SceneInfo* scene = timeline_scene(tl);
  if (!scene) throw UsageError("unknown scene '" + tl.scene + "'");
  apply_quick_look(ro, tl);

  const draw::PathMarks marks = path_marks(tl, *scene);
  // The views show where the camera goes and what its keys look at.
  std::vector<glm::dvec3> shown = marks.path;
  for (const CameraKey& k : tl.camera.keys) shown.push_back(k.pose.target);
  if (tl.camera.keys.empty()) shown.push_back(scene->default_camera.target);
  std::vector<draw::MapView> views = {
      draw::view_from_above(shown, scene->map_up, scene->map_ceiling, o.width)};
  if (scene->map_side_view) views.push_back(draw::view_from_side(shown, o.width));
  tl.width = o.width;  // the largest view, for the frame memory check
  for (const draw::MapView& v : views) tl.height = std::max(tl.height, v.height);

  const auto start = std::chrono::steady_clock::now();
  FramePipeline pipe(tl, timeline_backend(tl, ro));
  const int frame = int(std::lround(o.time * tl.fps.value()));
  std::vector<draw::MapPanel> panels;
  for (const draw::MapView& v : views) {
    FrameContext ctx = frame_context_at(tl, *scene, frame, o.time);
    ctx.pose = v.pose;
    ctx.width = v.width;
    ctx.height = v.height;
    finish_frame_context(ctx);
    panels.push_back({v, pipe.render_context(ctx).display});
  }
  char title[256];
  std::snprintf(title, sizeof title, "%s  camera path, %zu keys, scene at %.2f s",
                std::filesystem::path(tl.path).filename().string().c_str(), tl.camera.keys.size(),
                o.time);
  draw::path_map(panels, marks, title).write_png(o.output);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::fprintf(stderr, "wrote %s: %zu view%s of the path at %d pixels wide in %.1f s\n",
               o.output.c_str(), panels.size(), panels.size() == 1 ? "" : "s", o.width, seconds);
  return 0;
}

}  // namespace

void add_map_command(CLI::App& app, int& status) {
  auto o = std::make_shared<MapOptions>();
  CLI::App* cmd = app.add_subcommand(
      "map",
      "a picture of the camera path: the scene from above and from the side, fitted to "
      "the path, with its keys and the camera's direction");
  cmd->add_option("TIMELINE", o->render.timeline_path, "timeline file (TOML)")->required();
  cmd->add_option("-o,--output", o->output, "the map, a .png file")->required();
  cmd->add_option("--width", o->width, "width of each view in pixels (default 960)")
      ->check(CLI::Range(64, 8192));
  cmd->add_option("--time", o->time,
                  "video time (s) whose scene the map shows (default 0: the first frame's)");
  add_quick_look_options(cmd, o->render);
  cmd->callback([o, &status] { status = run_map(*o); });
}

}  // namespace sdfreel
