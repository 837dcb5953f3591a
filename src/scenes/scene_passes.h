#pragma once
// The compositing passes (render/compositing_passes.h) a scene gives, for the timeline's check of
// [output] passes, `sdfreel scenes` and the scene table.
#include <iterator>
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
  static const char* const names[] = {"samples", "sdf_evals", "id", "depth", "normal"};
  const bool given[] = {true, scene.counts_sdf_evals, bool(scene.make), scene.draws_surfaces,
                        scene.draws_surfaces};
  std::vector<std::string> passes;
  passes.reserve(std::size(names));  // no growth: GCC 14 warns (falsely) of one in push_back
  for (size_t i = 0; i < std::size(names); ++i)
    if (given[i]) passes.emplace_back(names[i]);
  return passes;
}

}  // namespace sdfreel
