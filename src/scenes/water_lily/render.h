#pragma once
// water_lily rendering: sphere tracing inside the slab of the lilies, soft shadows, the water
// (FBM bump, reflection of the lilies, Fresnel with the sky), the sky's FBM glow, and the seed's
// grading. Free functions of (inputs, uniforms) with the names the GLSL twin uses
// (shaders/water_lily/water_lily.glsl).
#include <glm/glm.hpp>

#include "scenes/scene.h"
#include "scenes/water_lily/uniforms.h"

namespace sdfreel::water_lily {

constexpr float MIN_HIT_EPS = 1e-5f;
constexpr float NO_HIT = -1.0f;
constexpr float BOUND_MARGIN = 0.05f;  // parts farther than this contribute their bound

// The marched scene at p: flowers and (if `leaves`) pads, bounds standing in for far parts.
float mapScene(const glm::vec3& p, bool leaves, const LilyUniforms& u, RayStats& stats);

// Sky radiance in direction d (unit): horizon to zenith gradient, FBM cloud glow, sun glow.
glm::vec3 skyColor(const glm::vec3& d, const LilyUniforms& u);

// Bumped water normal at (x, z), calmer with the distance `dist` from the eye.
glm::vec3 waterNormal(float x, float z, float dist, const LilyUniforms& u);

// Quilez's improved soft shadow from ro towards the unit direction ld: 0 shadowed .. 1 lit.
float softShadow(const glm::vec3& ro, const glm::vec3& ld, float k, int steps,
                 const LilyUniforms& u, RayStats& stats);

// Contrast, saturation and vignette of the seed, on a colour seen along rd.
glm::vec3 grade(const glm::vec3& col, const glm::vec3& rd, const LilyUniforms& u);

// Linear radiance along a primary ray.
glm::vec3 sceneRadiance(const Ray& ray, const LilyUniforms& u, RayStats& stats);

// sceneRadiance in two phases, for the eight-lane path (lanes.cpp), which marches the primary
// rays of a packet together: where the primary ray is marched (inside the field box, before the
// water) and, once the march gave t (or NO_HIT), everything else.
struct PrimarySpan {
  float eps_per_t;  // hit threshold per unit of path length
  float t_water;    // NO_HIT or where the ray meets the water
  bool water;       // the water is hit within max_dist
  float t0, t1;     // marched span; empty when t0 >= t1
};
PrimarySpan primarySpan(const Ray& ray, const LilyUniforms& u);
glm::vec3 radianceAfterMarch(const Ray& ray, const PrimarySpan& s, float t, const LilyUniforms& u,
                             RayStats& stats);

}  // namespace sdfreel::water_lily
