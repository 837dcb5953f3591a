#pragma once
// Light of the museum hall: the sun (directional, coming in through the west window, with
// analytic shadows of the window's opening and of the plinths and bench), a sky/ambient term and
// simple plausible materials (albedo, roughness-based Blinn-Phong specular with Schlick's Fresnel).
// The GLSL twin is shaders/museum/lighting.glsl (same constants, same operations).
#include <glm/glm.hpp>
#include <vector>

#include "render/shader_inputs.h"
#include "scenes/museum/hall_layout.h"

namespace sdfreel::museum {

// Towards the sun: low in the west, so it shines through the window onto the floor.
const glm::vec3 TO_SUN(-0.868287f, 0.434143f, 0.239994f);  // normalize(-1, 0.5, 0.2764)
const glm::vec3 SUN_RADIANCE(3.4f, 3.1f, 2.6f);            // irradiance on a facing surface
constexpr int MAX_OCCLUDERS = 8;

// What the hall's shading reads besides the fragment: the eye and the sun's occluders.
struct HallLight {
  glm::vec3 eye;
  std::vector<HallBox> occluders;  // at most MAX_OCCLUDERS
};

// 0..1: how much of the sun a point sees, through the window (soft at its edges) and past the
// occluders (hard).
float sun_visibility(const glm::vec3& p, const HallLight& light);

// Sky radiance in direction d (unit): gradient, ground below the horizon, the sun and its glow.
glm::vec3 sky(const glm::vec3& d);

// Radiance leaving a hall surface towards the eye. `normal` need not be unit.
glm::vec3 hall_radiance(const glm::vec3& p, const glm::vec3& normal, const glm::vec3& albedo,
                        float material, const HallLight& light);

// The occluders as GLSL uniforms u_occluder_lo[i], u_occluder_hi[i], u_occluder_count.
std::vector<ShaderUniform> light_uniforms(const HallLight& light);

}  // namespace sdfreel::museum
