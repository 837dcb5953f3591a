// Exhibit 1 in the sun's shadow map: the twin of exhibit_sun_depth() in
// src/scenes/museum/sdf_exhibit.cpp. The bound is drawn with the sun's view and front faces
// culled; each fragment marches the sun's ray through the object from where it enters the bound
// and writes the hit's depth in the map (no colour), or is discarded.
#include "common/det_math.glsl"
#include "sdf_morph/geometry.glsl"
#include "museum/exhibit_bound.glsl"

uniform MorphUniforms u_morph;
uniform mat4 u_exhibit_inv_model;
uniform float u_exhibit_scale;
uniform float u_exhibit_texel;  // the map's texel in object units
uniform vec3 u_sun_origin;
uniform vec3 u_sun_forward;
uniform vec3 u_sun_depth;  // near, 1 / (far - near), texel / (far - near)

in vec3 v_world_position;

void main() {
  precise vec3 o = (u_exhibit_inv_model * vec4(v_world_position, 1.0)).xyz;
  precise vec3 dl = (u_exhibit_inv_model * vec4(u_sun_forward, 0.0)).xyz * u_exhibit_scale;
  precise vec2 span = box_span(o, dl);
  precise float eps =
      u_morph.naive != 0 ? u_morph.hit_eps : dm_max(MIN_EPS, u_morph.hit_eps * u_exhibit_texel);
  precise float t = span.x;
  for (int i = 0; i < u_morph.max_steps && t < span.y; ++i) {
    precise float d = mapObject(o + dl * t, u_morph);
    if (d < eps) {
      precise vec3 world_hit = v_world_position + u_sun_forward * (t * u_exhibit_scale);
      gl_FragDepth = (dm_dot(world_hit - u_sun_origin, u_sun_forward) - u_sun_depth.x) *
                     u_sun_depth.y;
      return;
    }
    t = t + d;
  }
  discard;
}
