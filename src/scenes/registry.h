#pragma once
#include <string>
#include <vector>

#include "scenes/scene.h"

namespace sdfreel {

// All built-in scenes, in the order `sdfreel scenes` lists them.
const std::vector<SceneInfo>& all_scenes();
const SceneInfo* find_scene(const std::string& name);

}  // namespace sdfreel
