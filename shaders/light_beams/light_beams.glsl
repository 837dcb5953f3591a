// light_beams on the GPU path: the twin of src/scenes/light_beams/render.cpp (same functions,
// same names, same order of operations; glm::dot/length -> dotv/lengthv). A change there must be
// mirrored here: tests/osmesa compares the two backends' frames bit for bit.
#include "common/sample_loop.glsl"
#include "light_beams/shapes.glsl"
#include "light_beams/uniforms.glsl"
#include "light_beams/visibility.glsl"

const float AA_PIXELS = 1.5;
const float FRAME_X_SCALE = 0.5625;
const float FADE_INNER = 0.35;
const float FADE_OUTER = 1.4;
const float HIT_ID_NONE = 0.0;
const float HIT_ID_LIGHT = 1.0;
const float HIT_ID_OCCLUDER = 2.0;

float hitId(vec2 p) {
  if (shapeSDF(p, u_beams.shapes[OCCLUDER]) <= 0.0) return HIT_ID_OCCLUDER;
  for (int i = 0; i < OCCLUDER; ++i)
    if (u_beams.gain[i] > 0.0 && shapeSDF(p, u_beams.shapes[i]) <= 0.0) return HIT_ID_LIGHT;
  return HIT_ID_NONE;
}

float attenuation(float d) {
  return 1.0 / (u_beams.glow_constant + u_beams.glow_linear * d + u_beams.glow_quadratic * (d * d));
}

float cornerFade(vec2 p) {
  return 1.0 - dm_smoothstep(FADE_INNER, FADE_OUTER, lengthv(vec2(p.x * FRAME_X_SCALE, p.y)));
}

vec3 lightEmission(vec2 p, int i, float aa_width, inout RayStats stats) {
  stats.sdf_evals += 1u;
  precise float d = shapeSDF(p, u_beams.shapes[i]);
  precise float gain = u_beams.gain[i] * dm_mix(1.0, cornerFade(p), u_beams.fades[i]);
  if (d <= 0.0) return vec3(gain);
  precise float vis = lightVisibility(p, i, d, stats);
  precise vec3 glow = u_beams.color[i] * attenuation(d);
  precise float edge = dm_smoothstep(0.0, aa_width, d);
  return dm_mix(vec3(1.0), glow, edge) * (gain * vis);
}

vec3 radianceAt(vec2 p, float footprint, inout RayStats stats) {
  if (u_beams.hit_mask != 0) return vec3(hitId(p));
  precise float aa_width = AA_PIXELS * footprint;
  precise vec3 col = u_beams.background;
  for (int i = 0; i < OCCLUDER; ++i)
    if (u_beams.gain[i] > 0.0) col += lightEmission(p, i, aa_width, stats);
  return col;
}

vec3 radiance(Ray ray, inout RayStats stats) {
  if (!(ray.origin.z * ray.dir.z < 0.0))
    return u_beams.hit_mask != 0 ? vec3(HIT_ID_NONE) : u_beams.background;
  precise float t = -ray.origin.z / ray.dir.z;
  precise vec2 p = vec2(ray.origin.x + ray.dir.x * t, ray.origin.y + ray.dir.y * t);
  return radianceAt(p, ray.pixel_angle * t, stats);
}
