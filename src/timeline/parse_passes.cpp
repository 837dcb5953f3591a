// [output] passes: compositing passes carried by the EXR frames (render/compositing_passes.h),
// each one the scene gives (scenes/scene_passes.h).
#include <algorithm>

#include "render/compositing_passes.h"
#include "scenes/scene_passes.h"
#include "timeline/sections.h"
#include "timeline/suggest.h"

namespace sdfreel {

void parse_passes(const TomlReader& r, const toml::table& output, const SceneInfo& scene,
                  Timeline& tl) {
  const toml::node* n = output.get("passes");
  if (!n) return;
  const toml::array& names = r.array(*n, "output.passes");
  std::vector<std::string> known;
  for (const CompositingPass& p : compositing_passes()) known.push_back(p.name);
  const std::vector<std::string> given = scene_passes(scene);
  std::vector<std::string>& passes = tl.frame_options.passes;
  for (size_t i = 0; i < names.size(); ++i) {
    const toml::node& at = *names.get(i);
    const std::string name = r.string(at, "output.passes[" + std::to_string(i) + "]");
    if (!find_compositing_pass(name))
      r.fail(at,
             "unknown pass '" + name + "': use " + join(known, " or ") + did_you_mean(name, known));
    if (std::find(given.begin(), given.end(), name) == given.end())
      r.fail(at, "scene '" + scene.name + "' gives no '" + name + "' pass (it gives " +
                     join(given, " and ") + ")");
    if (std::find(passes.begin(), passes.end(), name) != passes.end())
      r.fail(at, "pass '" + name + "' is named twice");
    passes.push_back(name);
  }
  if (!passes.empty() && !tl.write_exr)
    r.fail(*n, "output.passes are channels of the EXR frames: add \"exr\" to output.frames");
}

}  // namespace sdfreel
