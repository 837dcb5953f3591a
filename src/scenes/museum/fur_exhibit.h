#pragma once
// Exhibit 3 on the third plinth: the fur case (scenes/fur/exhibit.h), scaled down to stand on the
// plinth top with its open side towards the hall's middle, its mesh passes drawn into the hall's
// colour and depth targets. Its look and physics are the fur scene's parameters named with a
// `fur_` prefix (fur_push_times, fur_sphere_length, ...), defaults as in the fur scene.
#include "scenes/museum/exhibits.h"

namespace sdfreel::museum {

constexpr int FUR_PLINTH = 2;
constexpr float FUR_HIT_ID_BASE = 4.0f;  // the shapes' hit ids are 5, 6, 7 (museum.cpp)
constexpr const char* FUR_PARAM_PREFIX = "fur_";

// The case's pose in exhibit space (plinth top at the origin).
glm::mat4 fur_case_pose();

// The fur's passes for the plinth's ExhibitPasses slot.
ExhibitPasses fur_exhibit();

}  // namespace sdfreel::museum
