#include "scenes/registry.h"

// Every built-in scene, one line each, in the order `sdfreel scenes` lists them. SCENE(name)
// stands for SceneInfo name_scene_info(), defined in src/scenes/<name>/<name>.cpp. Listed
// explicitly (no static registrars): static libraries drop unreferenced objects, and an explicit
// list keeps the order stable.
#define SDFREEL_SCENES(SCENE) \
  SCENE(sdf_morph)            \
  SCENE(lantern_festival)     \
  SCENE(water_lily)           \
  SCENE(light_beams)          \
  SCENE(lenticular_card)      \
  SCENE(museum)               \
  SCENE(fur)

namespace sdfreel {

#define SDFREEL_DECLARE_SCENE(name) SceneInfo name##_scene_info();
SDFREEL_SCENES(SDFREEL_DECLARE_SCENE)
#undef SDFREEL_DECLARE_SCENE

const std::vector<SceneInfo>& all_scenes() {
#define SDFREEL_SCENE_INFO(name) name##_scene_info(),
  static const std::vector<SceneInfo> scenes = {SDFREEL_SCENES(SDFREEL_SCENE_INFO)};
#undef SDFREEL_SCENE_INFO
  return scenes;
}

const SceneInfo* find_scene(const std::string& name) {
  for (const SceneInfo& s : all_scenes())
    if (s.name == name) return &s;
  return nullptr;
}

}  // namespace sdfreel
