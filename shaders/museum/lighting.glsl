// Light of the museum hall: the twin of src/scenes/museum/lighting.cpp (same constants and
// operations; see there for the model), the sun shadowed through its map (museum/sun_shadow.glsl).
#include "common/frame.glsl"
#include "common/noise.glsl"
#include "museum/paintings.glsl"
#include "museum/sun_shadow.glsl"

const float MATERIAL_FLOOR = 2.0;
const float MATERIAL_PAINTING = 3.0;

const vec3 TO_SUN = vec3(-0.868287, 0.434143, 0.239994);
const vec3 SUN_RADIANCE = vec3(3.4, 3.1, 2.6);

const vec3 SKY_ZENITH = vec3(0.12, 0.26, 0.6);
const vec3 SKY_HORIZON = vec3(0.55, 0.6, 0.68);
const vec3 GROUND = vec3(0.16, 0.15, 0.12);
const vec3 AMBIENT_UP = vec3(0.15, 0.16, 0.18);
const vec3 AMBIENT_DOWN = vec3(0.07, 0.06, 0.05);
const vec3 WINDOW_FILL = vec3(0.12, 0.13, 0.15);
const vec3 FROM_WINDOW = vec3(-0.957826, 0.287348, 0.0);
const float SUN_DISC_COS0 = 0.9994, SUN_DISC_COS1 = 0.9997;
const float SUN_DISC = 40.0;
const float SUN_GLOW = 0.5;
const float SPECULAR_F0 = 0.04;
const float FLOOR_ROUGHNESS = 0.45;
const float CANVAS_ROUGHNESS = 0.8;
const float PLANK_W = 0.2, PLANK_L = 1.2, SEAM = 0.03;
const uint PLANK_SEED = 7u;
const float NORMAL_OFFSET = 0.002;

uniform vec3 u_eye;

float power_of_two_power(float x, int k) {
  precise float y = x;
  for (int i = 0; i < k; ++i) y = y * y;
  return y;
}

vec3 floor_albedo(vec3 p, vec3 albedo) {
  precise float row = floor(p.z / PLANK_W);
  precise float shift = hash_to_unit(hash2i(int(row), 0, PLANK_SEED)) * PLANK_L;
  precise float plank = floor((p.x + shift) / PLANK_L);
  precise float tint = 0.8 + 0.4 * hash_to_unit(hash2i(int(row), int(plank), PLANK_SEED));
  precise float u = p.z / PLANK_W - row, v = (p.x + shift) / PLANK_L - plank;
  precise float seam = (u < SEAM || v < SEAM * PLANK_W / PLANK_L) ? 0.55 : 1.0;
  return albedo * (tint * seam);
}

// The twin of sun_visibility() with a map (the GL frame always has one).
float sun_visibility(vec3 p, vec3 n, float ndl) {
  precise vec3 q = p + n * NORMAL_OFFSET;
  return sun_map_visibility(q, ndl);
}

vec3 sky(vec3 d) {
  precise vec3 col = dm_mix(SKY_HORIZON, SKY_ZENITH, dm_smoothstep(0.0, 0.5, d.y));
  col = dm_mix(GROUND, col, dm_smoothstep(-0.02, 0.02, d.y));
  precise float c = dm_dot(d, TO_SUN);
  precise float glow = power_of_two_power(dm_max(c, 0.0), 5);
  precise float disc = dm_smoothstep(SUN_DISC_COS0, SUN_DISC_COS1, c);
  return col + SUN_RADIANCE * (SUN_GLOW * glow + SUN_DISC * disc);
}

vec3 hall_radiance(vec3 p, vec3 normal, vec3 albedo_in, float material) {
  precise vec3 n = normal / sqrt(dm_dot(normal, normal));
  bool is_floor = material == MATERIAL_FLOOR;
  bool is_painting = material >= MATERIAL_PAINTING;
  precise vec3 albedo = is_floor      ? floor_albedo(p, albedo_in)
                        : is_painting ? painting_albedo(p, int(material - MATERIAL_PAINTING))
                                      : albedo_in;
  precise float roughness = is_floor ? FLOOR_ROUGHNESS : is_painting ? CANVAS_ROUGHNESS : material;
  precise vec3 to_eye = u_eye - p;
  precise vec3 v = to_eye / sqrt(dm_dot(to_eye, to_eye));
  precise float ndl = dm_dot(n, TO_SUN);
  precise vec3 direct = vec3(0.0);
  if (ndl > 0.0) {
    precise float vis = sun_visibility(p, n, ndl);
    if (vis > 0.0) {
      precise vec3 hv = TO_SUN + v;
      precise vec3 h = hv / sqrt(dm_dot(hv, hv));
      int k = int(dm_clamp((1.0 - roughness) * 8.0, 1.0, 8.0));
      precise float e = float(1 << k);
      precise float lobe = power_of_two_power(dm_max(dm_dot(n, h), 0.0), k);
      precise float x = 1.0 - dm_max(dm_dot(h, v), 0.0);
      precise float fresnel = SPECULAR_F0 + (1.0 - SPECULAR_F0) * (x * x * x * x * x);
      precise float spec = (e + 8.0) / (8.0 * DM_PI) * lobe * fresnel;
      direct = SUN_RADIANCE * (vis * ndl) * (albedo + vec3(spec));
    }
  }
  precise vec3 ambient = dm_mix(AMBIENT_DOWN, AMBIENT_UP, 0.5 + 0.5 * n.y) +
                         WINDOW_FILL * (0.5 + 0.5 * dm_dot(n, FROM_WINDOW));
  return direct + albedo * ambient;
}
