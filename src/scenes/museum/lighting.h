#pragma once
// Light of the museum hall: the sun (directional, coming in through the west window, shadowed
// through the sun's shadow map of museum/sun_shadow.h), a sky/ambient term and simple plausible
// materials (albedo, roughness-based Blinn-Phong specular with Schlick's Fresnel). The GLSL twin is
// shaders/museum/lighting.glsl (same constants, same operations). The reflection probe, rendered
// on the CPU before the frame's passes draw the map, shades with an analytic sun test instead
// (the window's opening and the occluder boxes; C++ only).
#include <glm/glm.hpp>
#include <vector>

#include "render/image.h"
#include "render/shader_inputs.h"
#include "scenes/museum/hall_layout.h"
#include "scenes/museum/sun_shadow.h"

namespace sdfreel::museum {

// Towards the sun: low in the west, so it shines through the window onto the floor.
const glm::vec3 TO_SUN(-0.868287f, 0.434143f, 0.239994f);  // normalize(-1, 0.5, 0.2764)
const glm::vec3 SUN_RADIANCE(3.4f, 3.1f, 2.6f);            // irradiance on a facing surface

// What the hall's shading reads besides the fragment: the eye and the sun's occluders (for the
// analytic test).
struct HallLight {
  glm::vec3 eye;
  std::vector<HallBox> occluders;
};

// The frame's sun shadow map (the target SUN_MAP_TARGET) and its view; image null: no map, the
// analytic test.
struct SunMap {
  const ImageRGBA* image = nullptr;
  const SunView* view = nullptr;
  const SunMapWindows* windows = nullptr;  // optional: the image's windows (sun_map_windows.h)
};

// 0..1: how much of the sun a point p with unit normal n and ndl = dot(n, TO_SUN) > 0 sees: from
// the map (p moved NORMAL_OFFSET along n), or analytically through the window (soft at its edges)
// and past the occluders (hard).
float sun_visibility(const glm::vec3& p, const glm::vec3& n, float ndl, const HallLight& light,
                     const SunMap& map);

// Sky radiance in direction d (unit): gradient, ground below the horizon, the sun and its glow.
glm::vec3 sky(const glm::vec3& d);

// Radiance leaving a hall surface towards the eye. `normal` need not be unit.
glm::vec3 hall_radiance(const glm::vec3& p, const glm::vec3& normal, const glm::vec3& albedo,
                        float material, const HallLight& light, const SunMap& map);

// What lighting.glsl reads: u_eye and the sun's view (sun_view_uniforms).
std::vector<ShaderUniform> light_uniforms(const HallLight& light);

}  // namespace sdfreel::museum
