// The sun's shadow map read by the hall's shading: the twin of sun_map_visibility() in
// src/scenes/museum/sun_shadow.cpp (same constants, same operations; see there for the model).
// The map is the depth target "sun_shadow", GL's rows (row 0 at the bottom) as the sun's view
// rasterised them.
#include "common/det_math.glsl"

const float SUN_BIAS_TEXELS = 1.0;
const float SUN_SLOPE_TEXELS = 2.2;
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

// 0..1: the share of the 3x3 texels around p's that see the sun (ndl = dot(n, TO_SUN) > 0).
float sun_map_visibility(vec3 p, float ndl) {
  precise vec3 d = p - u_sun_origin;
  float size = u_sun_map.w;
  precise float tx = dm_clamp((dm_dot(d, u_sun_right) - u_sun_map.x) * u_sun_map.z, -2.0, size + 1.0);
  precise float ty = dm_clamp((dm_dot(d, u_sun_up) - u_sun_map.y) * u_sun_map.z, -2.0, size + 1.0);
  precise float slope = dm_min(sqrt(dm_max(1.0 - ndl * ndl, 0.0)) / ndl, SUN_MAX_SLOPE);
  precise float bias = (SUN_BIAS_TEXELS + SUN_SLOPE_TEXELS * slope) * u_sun_depth.z;
  precise float ref = sun_map_depth(dm_dot(d, u_sun_forward)) - bias;
  int x0 = int(floor(tx)), y0 = int(floor(ty)), n = int(size);
  int lit = 0;
  for (int j = -1; j <= 1; ++j)
    for (int i = -1; i <= 1; ++i) {
      int x = x0 + i, y = y0 + j;
      if (x < 0 || y < 0 || x >= n || y >= n) continue;  // behind the wall
      if (ref <= texelFetch(u_sun_shadow, ivec2(x, y), 0).r) ++lit;
    }
  precise float vis = float(lit) * (1.0 / 9.0);
  return vis;
}
