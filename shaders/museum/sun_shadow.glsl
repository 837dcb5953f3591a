// The sun's shadow map read by the hall's shading: the twin of sun_map_visibility() in
// src/scenes/museum/sun_shadow.cpp (same constants, same operations; see there for the model).
// The map is the depth target "sun_shadow", GL's rows (row 0 at the bottom) as the sun's view
// rasterised them.
#include "common/det_math.glsl"

const float SUN_BIAS_TEXELS = 1.0;
const float SUN_SLOPE_TEXELS = 3.0;
const int SUN_BOX_TEXELS = 5;  // the filter's box: about the sun's penumbra by the window
const int SUN_BOX_TAPS = SUN_BOX_TEXELS + 1;
const float SUN_MAX_SLOPE = 8.0;

uniform sampler2D u_sun_shadow;
uniform vec3 u_sun_origin;
uniform vec3 u_sun_right;
uniform vec3 u_sun_up;
uniform vec3 u_sun_forward;
uniform vec4 u_sun_map;    // u0, v0, 1 / texel, size
uniform vec3 u_sun_depth;  // near, 1 / (far - near), texel / (far - near)

float sun_map_depth(float w) {
  precise float z = (w - u_sun_depth.x) * u_sun_depth.y;
  return z;
}

// The weights of the SUN_BOX_TAPS texels k0 .. k0 + SUN_BOX_TEXELS under a box SUN_BOX_TEXELS
// wide centred at t (texel k spans [k, k + 1)): the end texels partly, 1 - f and f, the others
// wholly.
int box_weights(float t, out float w[SUN_BOX_TAPS]) {
  precise float left = t - 0.5 * float(SUN_BOX_TEXELS);
  precise float k = floor(left);
  precise float f = left - k;
  for (int i = 1; i < SUN_BOX_TEXELS; ++i) w[i] = 1.0;
  w[0] = 1.0 - f;
  w[SUN_BOX_TEXELS] = f;
  return int(k);
}

// 0..1: the lit share of a box SUN_BOX_TEXELS wide around p's texel position, its texels weighted
// by how much of each it covers (ndl = dot(n, TO_SUN) > 0).
float sun_map_visibility(vec3 p, float ndl) {
  precise vec3 d = p - u_sun_origin;
  float size = u_sun_map.w;
  float far = float(SUN_BOX_TEXELS);
  precise float tx =
      dm_clamp((dm_dot(d, u_sun_right) - u_sun_map.x) * u_sun_map.z, -far, size + far);
  precise float ty = dm_clamp((dm_dot(d, u_sun_up) - u_sun_map.y) * u_sun_map.z, -far, size + far);
  precise float slope = dm_min(sqrt(dm_max(1.0 - ndl * ndl, 0.0)) / ndl, SUN_MAX_SLOPE);
  precise float bias = (SUN_BIAS_TEXELS + SUN_SLOPE_TEXELS * slope) * u_sun_depth.z;
  precise float ref = sun_map_depth(dm_dot(d, u_sun_forward)) - bias;
  float wx[SUN_BOX_TAPS], wy[SUN_BOX_TAPS];
  int x0 = box_weights(tx, wx), y0 = box_weights(ty, wy), n = int(size);
  precise float lit = 0.0;
  int taps = 0, lit_taps = 0;  // of weight above 0: all lit is exactly 1, none exactly 0
  for (int j = 0; j < SUN_BOX_TAPS; ++j) {
    precise float row = 0.0;
    for (int i = 0; i < SUN_BOX_TAPS; ++i) {
      precise float w = wx[i] * wy[j];
      if (!(w > 0.0)) continue;
      ++taps;
      int x = x0 + i, y = y0 + j;
      if (x < 0 || y < 0 || x >= n || y >= n) continue;  // behind the wall
      if (ref <= texelFetch(u_sun_shadow, ivec2(x, y), 0).r) {
        row = row + wx[i];
        ++lit_taps;
      }
    }
    lit = lit + row * wy[j];
  }
  if (lit_taps == taps) return 1.0;
  precise float vis = lit_taps == 0 ? 0.0 : lit * (1.0 / float(SUN_BOX_TEXELS * SUN_BOX_TEXELS));
  return vis;
}
