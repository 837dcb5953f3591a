// `sdfreel scenes [NAME]`: the built-in scenes, or one scene's parameters.
#include <CLI/CLI.hpp>
#include <cstdio>

#include "cli/commands_impl.h"
#include "scenes/registry.h"
#include "scenes/scene_reference.h"
#include "timeline/suggest.h"
#include "timeline/toml_reader.h"

namespace sdfreel {

namespace {

int run_scenes(const std::string& name, bool markdown) {
  if (name.empty()) {
    if (markdown)
      throw UsageError("--markdown needs a scene name: `sdfreel scenes NAME --markdown`");
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
  const std::string text = markdown ? scene_reference_markdown(*s) : scene_reference_text(*s);
  std::fputs(text.c_str(), stdout);
  return 0;
}

}  // namespace

void add_scenes_command(CLI::App& app, int& status) {
  auto name = std::make_shared<std::string>();
  auto markdown = std::make_shared<bool>(false);
  CLI::App* cmd = app.add_subcommand("scenes", "list scenes, or one scene's parameters");
  cmd->add_option("NAME", *name, "scene name");
  cmd->add_flag("--markdown", *markdown,
                "print the scene's reference as the Markdown of its page under docs/scenes/");
  cmd->callback([name, markdown, &status] { status = run_scenes(*name, *markdown); });
}

}  // namespace sdfreel
