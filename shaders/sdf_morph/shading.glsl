// sdf_morph shading shared with the museum's exhibit 1 (shaders/museum/sdf_exhibit.frag): the
// key light, ambient and Fresnel of src/scenes/sdf_morph/render.cpp, and the mirror ray's
// direction and start of src/scenes/sdf_morph/march.h (same names and operations).
#include "sdf_morph/uniforms.glsl"

const float SURFACE_BIAS_FACTOR = 2.0;  // secondary rays start this many hit eps off
const float MIN_SURFACE_BIAS = 2e-3;

float surfaceBias(float eps) {
  precise float r_ = dm_max(MIN_SURFACE_BIAS, SURFACE_BIAS_FACTOR * eps);
  return r_;
}

vec3 reflectDir(vec3 d, vec3 n) {
  precise vec3 r_ = d - 2.0 * dm_dot(n, d) * n;
  return r_;
}

const vec3 KEY_COLOR = vec3(1.0, 0.96, 0.9);
const vec3 AMBIENT_SKY = vec3(0.22, 0.22, 0.24);
const vec3 AMBIENT_GROUND = vec3(0.08, 0.075, 0.07);

float schlick(float cos_theta, float f0) {
  precise float x = 1.0 - dm_clamp(cos_theta, 0.0, 1.0);
  precise float x2 = x * x;
  precise float r_ = f0 + (1.0 - f0) * (x2 * x2 * x);
  return r_;
}

vec3 ambientLight(vec3 n, MorphUniforms u) {
  precise vec3 r_ = u.env_intensity * dm_mix(AMBIENT_GROUND, AMBIENT_SKY, 0.5 + 0.5 * n.y);
  return r_;
}

vec3 diffuseLight(vec3 albedo, vec3 n, float shadow, float ao, MorphUniforms u) {
  precise float ndl = dm_max(dm_dot(n, u.boxes[0].dir), 0.0);
  precise vec3 r_ = albedo * (u.key_intensity * ndl * shadow * KEY_COLOR + ambientLight(n, u) * ao);
  return r_;
}

// The object: coloured diffuse base mixed with the mirror reflection by Schlick's Fresnel term.
vec3 shadeObjectLit(vec3 n, vec3 rd, vec3 reflection, float shadow, float ao, MorphUniforms u) {
  precise vec3 diffuse = diffuseLight(u.base_color, n, shadow, ao, u);
  precise float f = schlick(dm_dot(n, -rd), u.reflectivity);
  precise vec3 r_ = dm_mix(diffuse, reflection, f);
  return r_;
}
