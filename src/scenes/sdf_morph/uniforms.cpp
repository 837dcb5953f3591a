#include "scenes/sdf_morph/uniforms.h"

#include <string>

#include "scenes/common/march_uniforms.h"
#include "sdf/det_math.h"

namespace sdfreel::sdf_morph {
namespace {

// Share of the period each shape holds still at either end of the morph.
constexpr float MORPH_HOLD = 0.12f;
constexpr double TWO_PI_D = 6.283185307179586;
constexpr double MIN_PERIOD = 1e-3;
// Turn at TIME = 0, chosen so that with the default speed and period the mug (half a period in)
// shows its handle in profile.
constexpr double ROTATION_PHASE = 2.1;
constexpr float MIN_SHADOW_K = 1e-3f;  // softShadow divides by k

// Studio soft boxes, as seen from the object. Camera space of the default view: +z into the
// picture, +x to the left. The first is the key light: large, front left, high.
struct SoftBoxSpec {
  glm::vec3 toward;  // not necessarily unit
  glm::vec2 half_size;
  float corner;
  glm::vec3 radiance;
};
const SoftBoxSpec SOFTBOX_SPECS[SOFTBOX_COUNT] = {
    {{0.55f, 0.75f, -0.45f}, {0.45f, 0.55f}, 0.08f, {5.0f, 4.8f, 4.5f}},  // key
    {{-0.7f, 0.45f, 0.55f}, {0.12f, 0.7f}, 0.05f, {3.4f, 3.6f, 4.0f}},    // rim strip, back right
    {{0.1f, 0.95f, 0.3f}, {0.7f, 0.12f}, 0.05f, {2.4f, 2.4f, 2.4f}},      // overhead strip
};

glm::vec3 unit(const glm::vec3& v) {
  return v / dm::sqrt(glm::dot(v, v));
}

SoftBox make_soft_box(const SoftBoxSpec& s) {
  SoftBox b;
  b.dir = unit(s.toward);
  b.u = unit(glm::cross(b.dir, glm::vec3(0.0f, 1.0f, 0.0f)));  // horizontal (no box is overhead)
  b.v = glm::cross(b.u, b.dir);
  b.half_size = s.half_size;
  b.corner = s.corner;
  b.radiance = s.radiance;
  return b;
}

}  // namespace

float morph_weight(double scene_time, double period) {
  const double p = period > MIN_PERIOD ? period : MIN_PERIOD;
  const float angle = dm::wrap_phase(scene_time * (TWO_PI_D / p), TWO_PI_D);
  return dm::smoothstep(MORPH_HOLD, 1.0f - MORPH_HOLD, 0.5f - 0.5f * dm::cos(angle));
}

MorphUniforms make_morph_uniforms(const FrameContext& ctx) {
  const ParamValues& pv = ctx.params;
  MorphUniforms u;
  u.morph = morph_weight(ctx.scene_time, pv.scalar("morph_period"));
  const float angle =
      dm::wrap_phase(ctx.scene_time * pv.scalar("rotation_speed") + ROTATION_PHASE, TWO_PI_D);
  u.rot_cos = dm::cos(angle);
  u.rot_sin = dm::sin(angle);
  u.base_color = pv.vec3("color");
  u.reflectivity = float(pv.scalar("reflectivity"));
  u.key_intensity = float(pv.scalar("key_light_intensity"));
  u.shadow_k = dm::max(float(pv.scalar("shadow_softness")), MIN_SHADOW_K);
  u.env_intensity = float(pv.scalar("environment_intensity"));
  for (int i = 0; i < SOFTBOX_COUNT; ++i) u.boxes[i] = make_soft_box(SOFTBOX_SPECS[i]);
  copy_march_settings(ctx.march, u);
  return u;
}

std::vector<ShaderUniform> morph_shader_uniforms(const MorphUniforms& u) {
  UniformList list("u_morph");
  list.f("morph", u.morph)
      .f("rot_cos", u.rot_cos)
      .f("rot_sin", u.rot_sin)
      .v3("base_color", u.base_color)
      .f("reflectivity", u.reflectivity)
      .f("key_intensity", u.key_intensity)
      .f("shadow_k", u.shadow_k)
      .f("env_intensity", u.env_intensity);
  add_march_uniforms(list, u);
  std::vector<ShaderUniform> all = list.uniforms();
  for (int i = 0; i < SOFTBOX_COUNT; ++i) {
    const SoftBox& b = u.boxes[i];
    UniformList("u_morph.boxes[" + std::to_string(i) + "]")
        .v3("dir", b.dir)
        .v3("u", b.u)
        .v3("v", b.v)
        .v2("half_size", b.half_size)
        .f("corner", b.corner)
        .v3("radiance", b.radiance)
        .append_to(all);
  }
  return all;
}

}  // namespace sdfreel::sdf_morph
