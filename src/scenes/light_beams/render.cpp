#include "scenes/light_beams/render.h"

#include "scenes/light_beams/visibility.h"

namespace sdfreel::light_beams {
namespace {

using glm::vec3;

// Width of the white-to-colour blend at a light's edge, in pixels.
constexpr float AA_PIXELS = 1.5f;
// cornerFade: distance from the centre with x scaled by 9/16, so the default frame's edges are at
// 1 and its corners at sqrt(2).
constexpr float FRAME_X_SCALE = 0.5625f;
constexpr float FADE_INNER = 0.35f;
constexpr float FADE_OUTER = 1.4f;
constexpr float HIT_ID_NONE = 0.0f;
constexpr float HIT_ID_LIGHT = 1.0f;
constexpr float HIT_ID_OCCLUDER = 2.0f;

float hitId(vec2 p, const BeamsUniforms& u) {
  if (shapeSDF(p, u.shapes[OCCLUDER]) <= 0.0f) return HIT_ID_OCCLUDER;
  for (int i = 0; i < OCCLUDER; ++i)
    if (u.gain[i] > 0.0f && shapeSDF(p, u.shapes[i]) <= 0.0f) return HIT_ID_LIGHT;
  return HIT_ID_NONE;
}

}  // namespace

float attenuation(float d, const BeamsUniforms& u) {
  return 1.0f / (u.glow_constant + u.glow_linear * d + u.glow_quadratic * (d * d));
}

float cornerFade(vec2 p) {
  return 1.0f - dm::smoothstep(FADE_INNER, FADE_OUTER, lengthv(vec2(p.x * FRAME_X_SCALE, p.y)));
}

vec3 lightEmission(vec2 p, int i, float aa_width, const BeamsUniforms& u, RayStats& stats) {
  stats.sdf_evals += 1;
  const float d = shapeSDF(p, u.shapes[i]);
  const float gain = u.gain[i] * dm::mix(1.0f, cornerFade(p), u.fades[i]);
  // The seed's "intensity approaches infinity": the inside of a light is white.
  if (d <= 0.0f) return vec3(gain);
  const float vis = lightVisibility(p, i, d, u, stats);
  const vec3 glow = u.color[i] * attenuation(d, u);
  const float edge = dm::smoothstep(0.0f, aa_width, d);
  return dm::mix(vec3(1.0f), glow, edge) * (gain * vis);
}

vec3 radianceAt(vec2 p, float footprint, const BeamsUniforms& u, RayStats& stats) {
  if (u.hit_mask) return vec3(hitId(p, u));
  const float aa_width = AA_PIXELS * footprint;
  vec3 col = u.background;
  for (int i = 0; i < OCCLUDER; ++i)
    if (u.gain[i] > 0.0f) col += lightEmission(p, i, aa_width, u, stats);
  return col;
}

vec3 sceneRadiance(const Ray& ray, const BeamsUniforms& u, RayStats& stats) {
  // The camera must look at the plane from one side of it; otherwise it sees only the background.
  if (!(ray.origin.z * ray.dir.z < 0.0f)) return u.hit_mask ? vec3(HIT_ID_NONE) : u.background;
  const float t = -ray.origin.z / ray.dir.z;
  const vec2 p(ray.origin.x + ray.dir.x * t, ray.origin.y + ray.dir.y * t);
  return radianceAt(p, ray.pixel_angle * t, u, stats);
}

}  // namespace sdfreel::light_beams
