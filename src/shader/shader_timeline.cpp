#include "shader/shader_timeline.h"

#include <filesystem>

#include "shader/channel_images.h"
#include "shader/channel_tables.h"
#include "shader/shader_files.h"
#include "shader/shader_scene.h"

namespace sdfreel {

namespace fs = std::filesystem;

namespace {

std::vector<std::string> texture_dirs(const TomlReader& r, const toml::table* settings) {
  std::vector<std::string> dirs;
  const toml::node* n = settings ? settings->get("textures") : nullptr;
  if (!n) return dirs;
  const fs::path base = fs::path(r.file()).parent_path();
  for (const toml::node& d : r.array(*n, "shader.textures"))
    dirs.push_back((base / r.string(d, "shader.textures")).lexically_normal().string());
  return dirs;
}

void read_settings(const TomlReader& r, const toml::table& s, ShaderProject& p) {
  if (const toml::node* n = s.get("output"))
    p.display_referred = r.choice(*n, "shader.output", {"display", "linear"}) == "display";
  if (const toml::node* n = s.get("date")) {
    const std::vector<double> d = r.numbers(*n, "shader.date", 4);
    for (size_t i = 0; i < 4; ++i) p.date[i] = d[i];
  }
  if (const toml::node* n = s.get("non_finite"))
    p.non_finite_black = r.choice(*n, "shader.non_finite", {"black", "error"}) == "black";
  if (const toml::node* n = s.get("checkpoint_every")) {
    const auto* v = n->as_integer();
    if (!v || v->get() < 0 || v->get() > 1000000)
      r.fail(*n, "shader.checkpoint_every is a whole number of frames (0 keeps no checkpoints)");
    p.checkpoint_every = int(v->get());
  }
  if (const toml::node* n = s.get("cube_size")) {
    const auto* v = n->as_integer();
    if (!v || v->get() < 1 || v->get() > 4096)
      r.fail(*n, "shader.cube_size is Cube A's face size in texels, 1 to 4096 (the site's: 1024)");
    p.cube_size = int(v->get());
  }
  if (const toml::node* n = s.get("sample_rate")) {
    p.sample_rate = r.number(*n, "shader.sample_rate");
    if (!(p.sample_rate > 0)) r.fail(*n, "shader.sample_rate must be > 0");
  }
}

}  // namespace

std::shared_ptr<const SceneInfo> ShaderTimelineLoader::load(const TomlReader& r,
                                                            const toml::table& root,
                                                            const std::string& path,
                                                            const std::string& name) const {
  const toml::node* s = root.get("shader");
  const toml::table* settings = s ? &r.table(*s, "shader") : nullptr;
  if (settings)
    r.check_keys(*settings, "[shader]",
                 {"output", "textures", "date", "sample_rate", "non_finite", "checkpoint_every",
                  "cube_size"});
  auto project =
      std::make_shared<ShaderProject>(read_shader_files(path, texture_dirs(r, settings)));
  if (settings) read_settings(r, *settings, *project);
  if (const toml::node* c = root.get("channels"))
    apply_channel_tables(r, r.table(*c, "channels"), fs::path(r.file()).parent_path().string(),
                         *project);
  check_shader_project(*project);
  load_channel_images(*project);
  return make_shader_scene(project, name);
}

}  // namespace sdfreel
