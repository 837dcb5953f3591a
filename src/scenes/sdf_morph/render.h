#pragma once
// sdf_morph rendering: sphere tracing, normals, soft shadows, the studio environment that stands
// in for the seed's reflection probe, and shading. Free functions of (inputs, uniforms) with the
// names the GLSL port uses.
#include <glm/glm.hpp>

#include "scenes/scene.h"
#include "scenes/sdf_morph/uniforms.h"

namespace sdfreel::sdf_morph {

// Studio radiance seen in direction d (unit): gradient walls, a light pool on the backdrop and
// the soft boxes. Analytic, at infinity, like a reflection probe.
glm::vec3 environment(const glm::vec3& d, const MorphUniforms& u);

// Inigo Quilez's improved soft shadow towards direction rd from ro: 0 = fully shadowed, 1 = lit.
float softShadow(const glm::vec3& ro, const glm::vec3& rd, const MorphUniforms& u, RayStats& stats);

// Tetrahedron (4-tap) normal of the marched scene at p with finite-difference step e.
glm::vec3 calcNormal(const glm::vec3& p, float e, const MorphUniforms& u, RayStats& stats);

// IQ's 5-tap ambient occlusion along the normal: 0 = fully occluded, 1 = open.
float ambientOcclusion(const glm::vec3& p, const glm::vec3& n, const MorphUniforms& u,
                       RayStats& stats);
// Its last step, from the weighted sum of (tap height - distance).
float aoFromSum(float occ);

// ---- phases of sceneRadiance, shared with the eight-lane path (sdf_morph/lanes.cpp) ----
// The lanes run the marches, normals, shadows and occlusion; everything else is these functions.

// Where a primary ray is marched: [t0, t1) inside the group's sphere, before the floor.
struct PrimarySpan {
  float eps_per_t;  // hit threshold per unit of path length
  float t_floor;    // NO_HIT or where the floor is crossed
  bool floor_visible;
  float t0, t1;
};
PrimarySpan primarySpan(const Ray& ray, const MorphUniforms& u);

// The reflection ray off the object at p (normal n, direction r): its biased origin, floor
// crossing and marched span.
struct ReflectionSpan {
  glm::vec3 ro;
  float t_floor;
  float t0, t1;
};
ReflectionSpan reflectionSpan(const glm::vec3& p, const glm::vec3& n, const glm::vec3& r,
                              float t_before, float eps_per_t, const MorphUniforms& u);
// What the mirror sees: a marched surface with normal nq (object or pedestal, unshadowed;
// env_mirror = environment(reflectDir(r, nq))), or else the floor or the studio (env_r =
// environment(r)).
glm::vec3 shadeReflectionHit(const glm::vec3& nq, const glm::vec3& r, bool object,
                             const glm::vec3& env_mirror, const MorphUniforms& u);
glm::vec3 shadeReflectionMiss(const ReflectionSpan& span, const glm::vec3& r,
                              const glm::vec3& env_r, const MorphUniforms& u);

// Surfaces seen along rd with their soft shadow and ambient occlusion known, and the studio in
// the direction each needs: env_mirror = environment(reflectDir(rd, n)), env_rd = environment(rd).
glm::vec3 shadeObjectLit(const glm::vec3& n, const glm::vec3& rd, const glm::vec3& reflection,
                         float shadow, float ao, const MorphUniforms& u);
glm::vec3 shadePedestalLit(const glm::vec3& n, const glm::vec3& rd, float shadow, float ao,
                           const glm::vec3& env_mirror, const MorphUniforms& u);
glm::vec3 shadeFloorLit(const glm::vec3& p, float shadow, float ao, const glm::vec3& env_rd,
                        const MorphUniforms& u);

// Linear radiance along a primary ray.
glm::vec3 sceneRadiance(const Ray& ray, const MorphUniforms& u, RayStats& stats);

}  // namespace sdfreel::sdf_morph
