// The card on its stand: the twin of src/scenes/lenticular_card/card.cpp (same functions, same
// order of operations). A change there must be mirrored here: tests/osmesa compares the backends'
// frames bit for bit.
#include "common/surface_output.glsl"
#include "common/texture.glsl"
#include "lenticular_card/optics.glsl"

struct CardUniforms {
  mat4 world_to_local;
  vec3 light;
  float scroll;
  float ior, thickness;
  float gloss, ridge_noise;
  float lenses, views, view_height;
  int hit_mask;  // MarchSettings::hit_mask (0 or 1)
  int surface;   // MarchSettings::surface (common/surface_output.glsl)
  float hit_id_base;  // added to the ids
};
uniform CardUniforms u_card;
uniform sampler2D u_card_print;   // RGBA: the two interlaced prints, linear albedo, stacked
uniform sampler2D u_card_ridges;  // RG: tangent-space noise normal, x and y in [-1, 1]

const float CARD_HALF_WIDTH = 0.32;
const float CARD_HALF_HEIGHT = 0.24;
const float CARD_HALF_THICKNESS = 0.004;
const float CARD_CENTRE_Y = 0.30;
const float BASE_HALF_WIDTH = 0.22, BASE_HALF_HEIGHT = 0.03, BASE_HALF_DEPTH = 0.09;

const float CARD_BIG = 3.0e38;
const float HIT_ID_CARD = 1.0, HIT_ID_STAND = 2.0;
const float CARD_AMBIENT = 0.25, CARD_KEY = 1.1;
const float RIDGE_SLOPE = 0.35;
const float RIDGE_NOISE_ACROSS = 0.0625, RIDGE_NOISE_ALONG = 1.5;
const float CARD_F0 = 0.048;
const float SHININESS = 60.0, SPECULAR = 0.6;
const vec3 PAPER = vec3(0.72, 0.70, 0.66), EDGE = vec3(0.09, 0.09, 0.1);
const vec3 WOOD = vec3(0.12, 0.075, 0.045);
const vec3 ENV_LOW = vec3(0.05, 0.045, 0.04), ENV_HIGH = vec3(0.65, 0.68, 0.75);

float dot3(vec3 a, vec3 b) {
  precise float r = a.x * b.x + a.y * b.y + a.z * b.z;
  return r;
}

vec3 normalize3(vec3 v) {
  precise vec3 r = v * (1.0 / sqrt(dot3(v, v)));
  return r;
}

vec3 matte(vec3 albedo, vec3 n, vec3 light) {
  precise vec3 r = albedo * (CARD_AMBIENT + CARD_KEY * dm_max(dot3(n, light), 0.0));
  return r;
}

vec3 environment(vec3 r) {
  precise vec3 c = dm_mix(ENV_LOW, ENV_HIGH, dm_smoothstep(-0.1, 0.5, r.y));
  return c;
}

vec3 ridgeNormal(float lens_coord, float across, float y) {
  precise vec4 n = sampleBilinear(u_card_ridges,
                                  vec2(lens_coord * RIDGE_NOISE_ACROSS, y * RIDGE_NOISE_ALONG));
  precise vec3 r = normalize3(vec3(across * RIDGE_SLOPE + n.x * u_card.ridge_noise,
                                   n.y * u_card.ridge_noise, 1.0));
  return r;
}

vec3 to_local_point(mat4 m, vec3 p) {
  precise vec3 r = vec3(m[0][0] * p.x + m[1][0] * p.y + m[2][0] * p.z + m[3][0],
                        m[0][1] * p.x + m[1][1] * p.y + m[2][1] * p.z + m[3][1],
                        m[0][2] * p.x + m[1][2] * p.y + m[2][2] * p.z + m[3][2]);
  return r;
}

vec3 to_local_direction(mat4 m, vec3 d) {
  precise vec3 r = vec3(m[0][0] * d.x + m[1][0] * d.y + m[2][0] * d.z,
                        m[0][1] * d.x + m[1][1] * d.y + m[2][1] * d.z,
                        m[0][2] * d.x + m[1][2] * d.y + m[2][2] * d.z);
  return r;
}

bool hitBox(vec3 o, vec3 d, vec3 c, vec3 h, out float t, out int axis) {
  precise float t_near = -CARD_BIG, t_far = CARD_BIG;
  axis = -1;
  t = 0.0;
  for (int i = 0; i < 3; ++i) {
    if (d[i] == 0.0) {
      if (abs(o[i] - c[i]) > h[i]) return false;
      continue;
    }
    precise float t0 = (c[i] - h[i] - o[i]) / d[i], t1 = (c[i] + h[i] - o[i]) / d[i];
    if (t0 > t1) {
      precise float s = t0;
      t0 = t1;
      t1 = s;
    }
    if (t0 > t_near) {
      t_near = t0;
      axis = i;
    }
    if (t1 < t_far) t_far = t1;
  }
  t = t_near;
  return axis >= 0 && t_near <= t_far && t_near > 0.0;
}

vec3 frontColour(vec3 p, vec3 d) {
  precise float lenses = u_card.lenses, views = u_card.views, rows = u_card.view_height;
  precise float lens_coord = (p.x + CARD_HALF_WIDTH) * (lenses / (2.0 * CARD_HALF_WIDTH));
  precise float lens = dm_clamp(floor(lens_coord), 0.0, lenses - 1.0);
  precise float across = lens_coord - lens - 0.5;
  precise float vx = -d.x, vz = -d.z;
  precise float len = sqrt(vx * vx + vz * vz);
  precise float sin_theta = len > 0.0 ? vx / len : 0.0;
  precise float x = seen_print_position(lens + 0.5, sin_theta, u_card.ior, u_card.thickness);
  precise float column = dm_clamp(floor(x * views), 0.0, lenses * views - 1.0);
  precise float down = (CARD_CENTRE_Y + CARD_HALF_HEIGHT - p.y) * (0.5 / CARD_HALF_HEIGHT);
  precise float row = floor((down + u_card.scroll) * rows);
  precise vec3 albedo = texelFetchRepeat(u_card_print, column, row).rgb;
  precise vec3 n = ridgeNormal(lens_coord, across, p.y);
  precise vec3 v = normalize3(-d);
  precise vec3 diffuse = albedo * (CARD_AMBIENT + CARD_KEY * dm_max(u_card.light.z, 0.0));
  precise float cos_v = dm_max(dot3(n, v), 0.0);
  precise float m = 1.0 - cos_v, m2 = m * m;
  precise float fresnel = CARD_F0 + (1.0 - CARD_F0) * (m2 * m2 * m);
  precise vec3 r = n * (2.0 * dot3(n, v)) - v;
  precise vec3 h = normalize3(u_card.light + v);
  precise float spec = SPECULAR * CARD_KEY * dm_pow(dm_max(dot3(n, h), 0.0), SHININESS);
  precise vec3 c = diffuse * (1.0 - fresnel) + (environment(r) * fresnel + vec3(spec)) * u_card.gloss;
  return c;
}

bool shadeCard(Ray ray, out vec3 colour, out float t) {
  precise vec3 o = to_local_point(u_card.world_to_local, ray.origin);
  precise vec3 d = to_local_direction(u_card.world_to_local, ray.dir);
  precise float t_card = CARD_BIG, t_base = CARD_BIG;
  int a_card = -1, a_base = -1;
  bool card = hitBox(o, d, vec3(0.0, CARD_CENTRE_Y, 0.0),
                     vec3(CARD_HALF_WIDTH, CARD_HALF_HEIGHT, CARD_HALF_THICKNESS), t_card, a_card);
  bool base = hitBox(o, d, vec3(0.0, BASE_HALF_HEIGHT, 0.0),
                     vec3(BASE_HALF_WIDTH, BASE_HALF_HEIGHT, BASE_HALF_DEPTH), t_base, a_base);
  colour = vec3(0.0);
  t = 0.0;
  if (!card && !base) return false;
  bool on_card = card && (!base || t_card <= t_base);
  t = on_card ? t_card : t_base;
  int axis = on_card ? a_card : a_base;
  precise vec3 n = vec3(0.0);
  n[axis] = d[axis] < 0.0 ? 1.0 : -1.0;
  if (u_card.surface != SURFACE_COLOUR) {  // the local axis's normal in the world
    mat4 m = u_card.world_to_local;
    colour = surfaceOutput(u_card.surface, t, n[axis] * vec3(m[0][axis], m[1][axis], m[2][axis]));
    return true;
  }
  if (u_card.hit_mask != 0) {
    colour = vec3(u_card.hit_id_base + (on_card ? HIT_ID_CARD : HIT_ID_STAND));
  } else if (!on_card) {
    colour = matte(WOOD, n, u_card.light);
  } else if (axis == 2 && n.z > 0.0) {
    colour = frontColour(o + d * t, d);
  } else {
    colour = matte(axis == 2 ? PAPER : EDGE, n, u_card.light);
  }
  return true;
}
