// Lantern materials of seed 000: the twin of src/scenes/lantern_festival/shading.{h,cpp} (same
// names, constants and order of operations). The per-frame LightFrame arrives as u_light.
#include "lantern_festival/grid.glsl"

struct LightFrame {
  vec3 moon_dir;      // towards the moon
  vec3 moon_light;    // colour * intensity
  vec3 ambient;       // sky fill light
  vec3 candle_color;  // colour * intensity
  vec3 candle_local;  // candle position in the lantern frame
  float flicker_time;  // TIME * flicker_speed, wrapped to [0, FLICKER_PERIOD)
  float flicker_strength;
  vec3 paper_albedo, metal_albedo, wood_albedo;
};

uniform LightFrame u_light;

// Everything a material needs about the hit.
struct LanternHit {
  vec3 p;      // world position
  vec3 n;      // world normal (unit)
  vec3 view;   // unit vector from the hit towards the eye
  vec3 local;  // position in the lantern frame (lantern units)
  LanternCell cell;
};

// The seed's paper texture weights.
const float NORMAL_NOISE_WEIGHT = 0.35;
const float ALBEDO_NOISE_WEIGHT = 0.4;
const vec2 PAPER_UV_REPEAT = vec2(2.0, 1.0);
// Phong exponents and specular strengths per material.
const float PAPER_SHININESS = 8.0, PAPER_SPECULAR = 0.08;
const float METAL_SHININESS = 40.0, METAL_SPECULAR = 1.2;
const float WOOD_SHININESS = 6.0, WOOD_SPECULAR = 0.04;
// mix(0.3, 0.8, flickerValue) of the seed, and its value at the middle of the flicker range.
const float FLICKER_LO = 0.3, FLICKER_HI = 0.8, FLICKER_MID = 0.55;

// The seed's flicker: a sum of three cosines in [0.15, 0.85].
float flickerValue(float t) {
  precise float a = t * 2.0 * DM_PI, b = t * 3.0 * DM_PI, c = t * 2.5 * DM_PI;
  precise float v =
      (dm_cos(a) + 2.0) * 0.15 + (dm_cos(b) + 1.0) * 0.1 + (dm_cos(c) + 1.0) * 0.1;
  return v;
}

float candleStrength(LanternCell cell) {
  precise float flicker =
      dm_mix(FLICKER_LO, FLICKER_HI, flickerValue(u_light.flicker_time + cell.flicker_phase));
  return dm_max(0.0, dm_mix(FLICKER_MID, flicker, u_light.flicker_strength));
}

// The seed's cylindrical UVs (longitude with pi in place of the seed's 3.141).
vec2 calcCylindricalUVs(vec2 dir, vec3 p) {
  precise float longitude = dm_atan2(-dir.y, dir.x);  // [-pi, pi]
  precise vec2 uv = vec2((longitude / DM_PI) * 0.5 + 0.5, (p.y * 0.5) + 0.5);
  return uv;
}

// normalize(p.xz), with a fixed direction on the lantern axis where it is undefined.
vec2 radialDirection(vec3 p) {
  precise float len2 = p.x * p.x + p.z * p.z;
  if (!(len2 > 1e-20)) return vec2(1.0, 0.0);
  precise vec2 d = vec2(p.x, p.z) / sqrt(len2);
  return d;
}

struct Light {
  vec3 dir;       // towards the light, unit
  vec3 radiance;  // arriving (after 1/d^2)
};

vec3 reflect3(vec3 i, vec3 n) {
  precise vec3 r = i - n * (2.0 * dm_dot(n, i));
  return r;
}

float phong(vec3 n, vec3 l, vec3 v, float shininess) {
  precise float rv = dm_dot(reflect3(-l, n), v);
  return rv > 0.0 ? dm_pow(rv, shininess) : 0.0;
}

Light candleLight(LanternHit h) {
  precise vec3 light_pos = h.cell.center + toWorld(h.cell, u_light.candle_local * u_grid.scale);
  precise vec3 to_light = light_pos - h.p;
  precise float d2 = dm_max(dm_dot(to_light, to_light), 1e-6);
  // Lantern units for the falloff, so that a scaled lantern glows the same.
  precise float d2_local = d2 * u_grid.inv_scale * u_grid.inv_scale;
  precise vec3 dir = to_light / sqrt(d2);
  precise vec3 radiance = u_light.candle_color * (candleStrength(h.cell) / d2_local);
  return Light(dir, radiance);
}

// Opaque Lambert + Phong from the moon and the candle, plus the sky's fill light.
vec3 shadeOpaque(LanternHit h, vec3 albedo, float shininess, float specular) {
  Light candle = candleLight(h);
  precise float moon_ndl = dm_max(dm_dot(h.n, u_light.moon_dir), 0.0);
  precise float candle_ndl = dm_max(dm_dot(h.n, candle.dir), 0.0);
  precise vec3 col =
      albedo * (u_light.moon_light * moon_ndl + candle.radiance * candle_ndl + u_light.ambient);
  col += u_light.moon_light * (specular * phong(h.n, u_light.moon_dir, h.view, shininess));
  col += candle.radiance * (specular * phong(h.n, candle.dir, h.view, shininess));
  return col;
}

vec3 shadePaper(LanternHit h) {
  precise vec3 albedo = u_light.paper_albedo;
  precise vec2 normalXZ = radialDirection(h.local);
  precise vec2 uv = calcCylindricalUVs(normalXZ, h.local);
  precise vec3 normalNoise = vec3(sampleBilinear(u_paper_normal, uv * PAPER_UV_REPEAT));
  normalNoise = normalNoise * 2.0 - 1.0;
  precise float noise = sampleBilinear(u_paper_noise, uv * PAPER_UV_REPEAT).x;
  // The map is tangent-space: x along increasing longitude, y up the lantern, z along the normal.
  precise vec3 tangent = toWorld(h.cell, vec3(normalXZ.y, 0.0, -normalXZ.x));
  precise vec3 up = h.cell.to_local[1];
  precise vec3 bumped =
      h.n + (tangent * normalNoise.x + up * normalNoise.y + h.n * normalNoise.z) *
                NORMAL_NOISE_WEIGHT;
  precise vec3 n = safe_normalize(bumped);
  albedo *= 1.0 - noise * ALBEDO_NOISE_WEIGHT;

  // Candle: the seed's abs(n.l) * strength / d^2 lights both faces (translucent paper).
  Light candle = candleLight(h);
  precise vec3 light = candle.radiance * abs(dm_dot(n, candle.dir));
  precise float moon_ndl = dm_max(dm_dot(n, u_light.moon_dir), 0.0);
  precise vec3 col = albedo * (light + u_light.moon_light * moon_ndl + u_light.ambient);
  col += u_light.moon_light *
         (PAPER_SPECULAR * phong(n, u_light.moon_dir, h.view, PAPER_SHININESS));
  col += candle.radiance * (PAPER_SPECULAR * phong(n, candle.dir, h.view, PAPER_SHININESS));
  return col;
}

vec3 shadeMetal(LanternHit h) {
  return shadeOpaque(h, u_light.metal_albedo, METAL_SHININESS, METAL_SPECULAR);
}

vec3 shadeWood(LanternHit h) {
  return shadeOpaque(h, u_light.wood_albedo, WOOD_SHININESS, WOOD_SPECULAR);
}

// The seed's material choice (nearestPart) and dispatch.
vec3 shadeLantern(LanternHit h) {
  int part = nearestPart(h.local);
  if (part == PART_METAL) return shadeMetal(h);
  if (part == PART_PAPER) return shadePaper(h);
  return shadeWood(h);
}
