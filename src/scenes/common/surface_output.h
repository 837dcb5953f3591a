#pragma once
// The depth and normal passes' frame (render/compositing_passes.h): what a scene shows instead of
// a colour when MarchSettings::surface asks, at the primary ray's surface. GLSL twin:
// shaders/common/surface_output.glsl.
#include <glm/glm.hpp>

#include "render/quality.h"

namespace sdfreel {

// A surface at distance t along the ray with unit normal n.
inline glm::vec3 surfaceOutput(int mode, float t, const glm::vec3& n) {
  return mode == SURFACE_DISTANCE ? glm::vec3(t) : n;
}
// No surface.
inline glm::vec3 noSurface(int mode) {
  return glm::vec3(mode == SURFACE_DISTANCE ? NO_SURFACE_DISTANCE : 0.0f);
}

}  // namespace sdfreel
