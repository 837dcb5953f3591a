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

// Where the sun's shadow ray for the light through a backlit petal starts: from p (normal n, the
// side away from the sun) along -n out of the flower, stepping by the depth inside. From just
// under the surface it would start inside the petal, find it, and let no light through.
constexpr int PETAL_EXIT_STEPS = 8;
glm::vec3 throughPetal(const glm::vec3& p, const glm::vec3& n, float bias, const LilyUniforms& u,
                       RayStats& stats);

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

// radianceAfterMarch in three steps, so that the lanes trace the rays of eight pixels' shading
// together: shadeBegin (normal, material, and which secondary rays the pixel needs),
// traceSecondary (one pixel's soft shadows and reflection march; the lanes have their twin), and
// shadeEnd (the lighting with their answers).
struct SecondaryRays {
  bool sun = false, fill = false, reflect = false;  // which rays the pixel traces
  glm::vec3 sun_origin{0.0f}, fill_origin{0.0f};    // soft shadows towards u.sun_dir, u.fill_dir
  glm::vec3 reflect_origin{0.0f}, reflect_dir{0.0f};
  float reflect_t0 = 0.0f, reflect_t1 = 0.0f;  // marched span of the reflection (flowers only)
  float reflect_eps_per_t = 0.0f, reflect_t_before = 0.0f;
  float sun_shadow = 1.0f, fill_shadow = 1.0f, reflect_t = NO_HIT;  // the answers
};
struct Surface {
  glm::vec3 albedo{0.0f};
  float translucent = 0.0f;  // 0 opaque .. 1 a thin petal
  float shininess = 0.0f;    // 0: no highlight
  float specular = 0.0f;     // the highlight's weight
  glm::vec3 tilt{0.0f};      // added to the normal before lighting (a water drop's dome)
};
constexpr int SHADE_DONE = 0;  // sky, underwater or hit mask: col is the answer
constexpr int SHADE_SURFACE = 1;
constexpr int SHADE_WATER = 2;
struct PixelShade {
  int kind = SHADE_DONE;
  glm::vec3 col{0.0f};
  glm::vec3 rd{0.0f};
  float dist = 0.0f;
  glm::vec3 p{0.0f}, n{0.0f};  // the surface's or the water's point and normal
  Surface surface;
  SecondaryRays rays;
};
PixelShade shadeBegin(const Ray& ray, const PrimarySpan& s, float t, const LilyUniforms& u,
                      RayStats& stats);
void traceSecondary(SecondaryRays& rays, const LilyUniforms& u, RayStats& stats);
glm::vec3 shadeEnd(const PixelShade& ps, const LilyUniforms& u);

}  // namespace sdfreel::water_lily
