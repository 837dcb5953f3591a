// `sdfreel scenes [NAME]`: the built-in scenes, or one scene's parameters.
#include <CLI/CLI.hpp>
#include <cstdio>

#include "cli/commands_impl.h"
#include "scenes/registry.h"
#include "scenes/scene_passes.h"
#include "timeline/suggest.h"
#include "timeline/toml_reader.h"

namespace sdfreel {

namespace {

std::string format_values(const std::vector<double>& v) {
  std::string s;
  char b[32];
  for (size_t i = 0; i < v.size(); ++i) {
    std::snprintf(b, sizeof b, "%g", v[i]);
    s += (i ? ", " : "") + std::string(b);
  }
  return v.size() > 1 ? "[" + s + "]" : s;
}

int run_scenes(const std::string& name) {
  if (name.empty()) {
    for (const SceneInfo& s : all_scenes())
      std::printf("%-20s %s\n", s.name.c_str(), s.description.c_str());
    return 0;
  }
  const SceneInfo* s = find_scene(name);
  if (!s) {
    std::vector<std::string> names;
    for (const SceneInfo& scene : all_scenes()) names.push_back(scene.name);
    const std::string hint = did_you_mean(name, names);
    throw UsageError("unknown scene '" + name + "'" +
                     (hint.empty() ? "; `sdfreel scenes` lists them" : hint));
  }
  std::printf("%s\n  %s\n\n", s->name.c_str(), s->description.c_str());
  const CameraPose& c = s->default_camera;
  std::printf("default camera: position = [%g, %g, %g], target = [%g, %g, %g], fov = %g\n",
              c.position.x, c.position.y, c.position.z, c.target.x, c.target.y, c.target.z,
              c.fov_deg);
  std::printf("compositing passes ([output] passes): %s\n\n", join(scene_passes(*s), ", ").c_str());
  std::printf("%-24s %-20s %-18s %s\n", "parameter", "default", "range", "meaning");
  for (const ParamSpec& p : s->params) {
    char range[64];
    std::snprintf(range, sizeof range, "%g .. %g", p.min, p.max);
    std::printf("%-24s %-20s %-18s %s\n", p.name.c_str(), format_values(p.def).c_str(), range,
                p.doc.c_str());
  }
  return 0;
}

}  // namespace

void add_scenes_command(CLI::App& app, int& status) {
  auto name = std::make_shared<std::string>();
  CLI::App* cmd = app.add_subcommand("scenes", "list scenes, or one scene's parameters");
  cmd->add_option("NAME", *name, "scene name");
  cmd->callback([name, &status] { status = run_scenes(*name); });
}

}  // namespace sdfreel
