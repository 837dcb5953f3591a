// The night sky: the twin of moon() and skyFrom() in src/scenes/lantern_festival/sky.cpp (the
// equirect texture itself is generated on the host and arrives as u_sky_env). The per-frame
// SkyFrame arrives as u_sky.
#include "common/sdf.glsl"
#include "lantern_festival/generated_textures.glsl"

// Moon: disc half-angle, halo falloff and strength, maria (as in the C++).
const float MOON_RADIUS_RAD = 0.018;
const float MOON_HALO_SHARPNESS = 900.0, MOON_HALO_GAIN = 0.35;
const float MOON_GLOW_SHARPNESS = 12.0, MOON_GLOW_GAIN = 0.05;
const float MOON_MARIA_DEPTH = 0.35, MOON_MARIA_SCALE = 0.5;
// The seed's fog: clamp(mix(1, -1.5, y)), smoothstep, then the 15th power.
const float FOG_MIX_TO = -1.5;

struct SkyFrame {
  float intensity;
  vec3 moon_dir;  // towards the moon, unit
  vec3 moon_right, moon_up;
  vec3 moon_disc;  // radiance of the disc
  vec3 moon_glow;  // radiance of the halo at its centre
  float moon_cos_inner, moon_cos_outer;
  vec3 fog_color;
  float horizon_fog;
};

uniform SkyFrame u_sky;

float pow15(float x) {
  precise float x2 = x * x, x4 = x2 * x2, x8 = x4 * x4;
  precise float r = x8 * x4 * x2 * x;
  return r;
}

vec3 moon(vec3 dir) {
  precise float c = dm_dot(dir, u_sky.moon_dir);
  // Halo: exp(-k (1 - cos)) ~ a Gaussian in the angle; a tight corona plus a wide glow.
  precise float one_minus = 1.0 - c;
  precise float halo = MOON_HALO_GAIN * dm_exp(-MOON_HALO_SHARPNESS * one_minus) +
                       MOON_GLOW_GAIN * dm_exp(-MOON_GLOW_SHARPNESS * one_minus);
  precise vec3 col = u_sky.moon_glow * halo;
  if (c > u_sky.moon_cos_outer) {
    precise float disc = dm_smoothstep(u_sky.moon_cos_outer, u_sky.moon_cos_inner, c);
    // Maria: the paper's blotch map stretched across the disc (one texture period per radius).
    precise vec2 q = vec2(dm_dot(dir, u_sky.moon_right), dm_dot(dir, u_sky.moon_up));
    precise vec2 uv = q * (MOON_MARIA_SCALE / MOON_RADIUS_RAD);
    precise float maria = sampleBilinear(u_paper_noise, uv).x;
    col += u_sky.moon_disc * (disc * (1.0 - MOON_MARIA_DEPTH * maria));
  }
  return col;
}

// The seed's sky(): environment (sharp, or the blurred copy for reflections) + moon, then fog.
vec3 skyFrom(sampler2D environment, vec3 dir_in) {
  precise vec3 dir = safe_normalize(dir_in);
  precise float fog = dm_clamp(dm_mix(1.0, FOG_MIX_TO, dir.y), 0.0, 1.0);
  fog = dm_smoothstep(0.0, 1.0, fog);
  fog = pow15(fog);
  precise float thetaa = dm_acos(dir.y);
  precise float phii = dm_atan2(dir.z, dir.x);
  precise vec4 env =
      sampleBilinearEquirect(environment, vec2(phii / DM_TWO_PI, thetaa / DM_PI));
  precise vec3 col = vec3(env) * u_sky.intensity + moon(dir);
  precise vec3 r = dm_mix(col, u_sky.fog_color, fog * u_sky.horizon_fog);
  return r;
}

vec3 sky(vec3 dir) { return skyFrom(u_sky_env, dir); }
vec3 skyReflected(vec3 dir) { return skyFrom(u_sky_env_blurred, dir); }
