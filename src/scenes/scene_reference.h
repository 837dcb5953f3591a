#pragma once
// A scene's reference as `sdfreel scenes NAME` prints it, in text for a terminal or in Markdown
// for its page under docs/scenes/ (the page's copy is checked against this by a test, so the
// parameter tables cannot drift from the code).
#include <string>
#include <vector>

#include "scenes/scene.h"

namespace sdfreel {

// "0.5", or "[1, 0.5, 0]" for a vector.
std::string format_param_values(const std::vector<double>& values);

// Default camera, compositing passes and the parameter table, as plain text.
std::string scene_reference_text(const SceneInfo& scene);

// The same as Markdown, between the marker lines that scripts/update-scene-pages.sh replaces.
std::string scene_reference_markdown(const SceneInfo& scene);

}  // namespace sdfreel
