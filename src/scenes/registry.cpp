#include "scenes/registry.h"

namespace sdfreel {

// Each scene file defines one of these. Listed explicitly (no static registrars): static
// libraries drop unreferenced objects, and an explicit list keeps the order stable.
SceneInfo sdf_morph_scene_info();
SceneInfo lantern_festival_scene_info();
SceneInfo water_lily_scene_info();

const std::vector<SceneInfo>& all_scenes() {
  static const std::vector<SceneInfo> scenes = {
      sdf_morph_scene_info(),
      lantern_festival_scene_info(),
      water_lily_scene_info(),
  };
  return scenes;
}

const SceneInfo* find_scene(const std::string& name) {
  for (const SceneInfo& s : all_scenes())
    if (s.name == name) return &s;
  return nullptr;
}

}  // namespace sdfreel
