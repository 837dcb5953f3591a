#pragma once
// The compositing passes (render/compositing_passes.h) a scene gives, for the timeline's check of
// [output] passes, `sdfreel scenes` and the scene table.
#include <string>
#include <vector>

#include "scenes/scene.h"

namespace sdfreel {

// Every scene gives "samples"; "sdf_evals" those whose marches count their evaluations
// (SceneInfo::counts_sdf_evals); "id" the built-in scenes, which draw their surfaces' numbers
// instead of colours when asked (MarchSettings::hit_mask), a user's shader does not; "depth" and
// "normal" those that draw their surfaces' distance and normal when asked
// (SceneInfo::draws_surfaces, MarchSettings::surface). Inline: the
// timeline library, which links no scene code, checks [output] passes with it.
inline std::vector<std::string> scene_passes(const SceneInfo& scene) {
  std::vector<std::string> passes = {"samples"};
  if (scene.counts_sdf_evals) passes.push_back("sdf_evals");
  if (scene.make) passes.push_back("id");
  if (scene.draws_surfaces) {
    passes.push_back("depth");
    passes.push_back("normal");
  }
  return passes;
}

}  // namespace sdfreel
