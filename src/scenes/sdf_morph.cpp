// PLACEHOLDER until the sdf_morph scene lands: metadata only.
#include "scenes/scene.h"

namespace sdfreel {

SceneInfo sdf_morph_scene_info() {
  SceneInfo info;
  info.name = "sdf_morph";
  info.description = "A ray-marched object morphing between a torus and a mug (seed 004).";
  info.params = {
      {"morph_period", 1, {6.0}, 0.5, 120.0, "seconds for torus -> mug -> torus"},
      {"color", 3, {0.9, 0.6, 0.3}, 0.0, 1.0, "base colour (linear Rec.709)"},
      {"reflectivity", 1, {0.6}, 0.0, 1.0, "share of mirror reflection"},
  };
  info.default_camera = CameraPose{{0.0, 1.5, -4.0}, {0.0, 0.6, 0.0}, 40.0, 0.0};
  info.shader = "sdf_morph.glsl";
  info.make = [] { return std::unique_ptr<Scene>(); };
  return info;
}

}  // namespace sdfreel
