#include "scenes/water_lily/uniforms.h"

#include <string>

#include "scenes/common/march_uniforms.h"
#include "scenes/water_lily/geometry.h"
#include "sdf/det_math.h"

namespace sdfreel::water_lily {
namespace {

constexpr double TWO_PI_D = 6.283185307179586;
// Curl: each flower's rate swings by CURL_SWING around curl_amount with its own phase.
constexpr double CURL_SPEED = 0.6;  // radians of phase per second
constexpr float CURL_SWING = 0.22f;
// The drifting leaf: an ellipse of drift * (1, DRIFT_Z) traced at these angular speeds.
constexpr double DRIFT_SPEED_X = 0.21;
constexpr double DRIFT_SPEED_Z = 0.13;
constexpr float DRIFT_Z = 0.6f;
// The water's time coordinate wraps every WATER_PERIOD noise units (a float TIME of 1e6 s would
// move it in steps); over the last WATER_BLEND units before the wrap the noise at w and at
// w - WATER_PERIOD are cross-faded, so the wrap is seamless.
constexpr double WATER_PERIOD = 512.0;
constexpr double WATER_BLEND = 16.0;
constexpr double CLOUD_SPEED = 0.004;
constexpr double CLOUD_PERIOD = 4096.0;
constexpr float MIN_SHADOW_K = 1e-3f;

glm::vec3 unit(const glm::vec3& v) {
  return v / dm::sqrt(glm::dot(v, v));
}

glm::vec3 from_angles(double elevation_deg, double azimuth_deg) {
  const float el = float(elevation_deg * (TWO_PI_D / 360.0));
  const float az = float(azimuth_deg * (TWO_PI_D / 360.0));
  return glm::vec3(dm::cos(el) * dm::sin(az), dm::sin(el), dm::cos(el) * dm::cos(az));
}

}  // namespace

LilyUniforms make_lily_uniforms(const FrameContext& ctx) {
  const ParamValues& pv = ctx.params;
  const double time = ctx.scene_time;
  LilyUniforms u;
  const float curl_amount = float(pv.scalar("curl_amount"));
  float max_curl = 0.0f;
  for (int f = 0; f < FLOWER_COUNT; ++f) {
    const float phase = dm::wrap_phase(time * CURL_SPEED + double(FLOWERS[f].phase), TWO_PI_D);
    const float c = curl_amount * (1.0f + CURL_SWING * dm::sin(phase));
    u.curl[f] = dm::clamp(c, 0.0f, MAX_CURL);
    max_curl = dm::max(max_curl, u.curl[f]);
  }
  for (int l = 0; l < PETAL_LAYERS; ++l)
    u.petal_lipschitz[l] = petalLipschitz(LAYERS[l], max_curl * LAYERS[l].curl);
  for (int i = 0; i < LEAF_COUNT; ++i) u.leaf_lipschitz[i] = leafLipschitz(LEAVES[i]);

  const float drift = float(pv.scalar("leaf_drift"));
  const float ax = dm::wrap_phase(time * DRIFT_SPEED_X, TWO_PI_D);
  const float az = dm::wrap_phase(time * DRIFT_SPEED_Z, TWO_PI_D);
  u.drift_offset = glm::vec2(drift * dm::sin(ax), drift * DRIFT_Z * dm::sin(az));

  const double w = time * pv.scalar("water_speed");
  const float wa = dm::wrap_phase(w, WATER_PERIOD);
  u.water_time_a = wa;
  u.water_time_b = float(double(wa) - WATER_PERIOD);
  const double into_blend = double(wa) - (WATER_PERIOD - WATER_BLEND);
  u.water_blend = into_blend > 0.0 ? float(into_blend / WATER_BLEND) : 0.0f;
  u.cloud_shift = dm::wrap_phase(time * CLOUD_SPEED, CLOUD_PERIOD);

  u.sun_dir = from_angles(pv.scalar("sun_elevation"), pv.scalar("sun_azimuth"));
  u.sun_color = pv.vec3("sun_color") * float(pv.scalar("sun_intensity"));
  u.fill_dir = unit(glm::vec3(-0.25f, 1.0f, -0.35f));
  u.water_bump = float(pv.scalar("water_bump"));
  u.translucency = float(pv.scalar("petal_translucency"));
  u.droplets = float(pv.scalar("droplets"));
  u.contrast = float(pv.scalar("contrast"));
  u.saturation = float(pv.scalar("saturation"));
  u.vignette = float(pv.scalar("vignette"));
  u.fog_distance = float(pv.scalar("fog_distance"));
  u.shadow_k = dm::max(float(pv.scalar("shadow_softness")), MIN_SHADOW_K);

  u.cam_right = ctx.camera.right;
  u.cam_up = ctx.camera.up;
  u.cam_forward = ctx.camera.forward;
  u.inv_tan_half_fov = 1.0f / ctx.camera.tan_half_fov;
  u.inv_aspect = float(ctx.height) / float(ctx.width);

  copy_march_settings(ctx.march, u);
  return u;
}

std::vector<ShaderUniform> lily_shader_uniforms(const LilyUniforms& u) {
  const auto array = [](const float* v, int n) { return std::vector<float>(v, v + n); };
  UniformList list("u_lily");
  list.add("curl", 1, array(u.curl, FLOWER_COUNT))
      .add("petal_lipschitz", 1, array(u.petal_lipschitz, PETAL_LAYERS))
      .add("leaf_lipschitz", 1, array(u.leaf_lipschitz, LEAF_COUNT))
      .v2("drift_offset", u.drift_offset)
      .f("water_time_a", u.water_time_a)
      .f("water_time_b", u.water_time_b)
      .f("water_blend", u.water_blend)
      .f("cloud_shift", u.cloud_shift)
      .v3("sun_dir", u.sun_dir)
      .v3("sun_color", u.sun_color)
      .v3("fill_dir", u.fill_dir)
      .f("water_bump", u.water_bump)
      .f("translucency", u.translucency)
      .f("droplets", u.droplets)
      .f("contrast", u.contrast)
      .f("saturation", u.saturation)
      .f("vignette", u.vignette)
      .f("fog_distance", u.fog_distance)
      .f("shadow_k", u.shadow_k)
      .v3("cam_right", u.cam_right)
      .v3("cam_up", u.cam_up)
      .v3("cam_forward", u.cam_forward)
      .f("inv_tan_half_fov", u.inv_tan_half_fov)
      .f("inv_aspect", u.inv_aspect);
  add_march_uniforms(list, u);
  return list.uniforms();
}

}  // namespace sdfreel::water_lily
