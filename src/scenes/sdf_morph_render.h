#pragma once
// sdf_morph rendering: sphere tracing, normals, soft shadows, the studio environment that stands
// in for the seed's reflection probe, and shading. Free functions of (inputs, uniforms) with the
// names the GLSL port uses.
#include <glm/glm.hpp>

#include "scenes/scene.h"
#include "scenes/sdf_morph_uniforms.h"

namespace sdfreel::sdf_morph {

// Studio radiance seen in direction d (unit): gradient walls, a light pool on the backdrop and
// the soft boxes. Analytic, at infinity, like a reflection probe.
glm::vec3 environment(const glm::vec3& d, const MorphUniforms& u);

// Inigo Quilez's improved soft shadow towards direction rd from ro: 0 = fully shadowed, 1 = lit.
float softShadow(const glm::vec3& ro, const glm::vec3& rd, const MorphUniforms& u, RayStats& stats);

// Tetrahedron (4-tap) normal of the marched scene at p with finite-difference step e.
glm::vec3 calcNormal(const glm::vec3& p, float e, const MorphUniforms& u, RayStats& stats);

// Linear radiance along a primary ray.
glm::vec3 sceneRadiance(const Ray& ray, const MorphUniforms& u, RayStats& stats);

}  // namespace sdfreel::sdf_morph
