// Exhibit 1: the sdf_morph object ray-marched in object space inside its bounding box, drawn with
// front faces culled; the twin of shade_exhibit() in src/scenes/museum/sdf_exhibit.cpp (see there).
// Writes the hit's window depth to gl_FragDepth, so the depth test composites it with the hall.
#include "common/camera.glsl"
#include "common/surface_output.glsl"
#include "sdf_morph/geometry.glsl"
#include "sdf_morph/shading.glsl"
#include "museum/lighting.glsl"
#include "museum/probe.glsl"
#include "museum/exhibit_bound.glsl"

const float NORMAL_EPS = 1e-3;

uniform MorphUniforms u_morph;
uniform mat4 u_exhibit_inv_model;
uniform float u_exhibit_scale;
uniform vec3 u_exhibit_to_world0;
uniform vec3 u_exhibit_to_world1;
uniform vec3 u_exhibit_to_world2;

in vec3 v_world_position;
in vec3 v_world_normal;
in vec2 v_uv;
flat in vec4 v_instance_data;

layout(location = 0) out vec4 frag_color;

vec3 object_normal(vec3 p) {
  const vec3 a = vec3(1.0, -1.0, -1.0), b = vec3(-1.0, -1.0, 1.0), c = vec3(-1.0, 1.0, -1.0),
             d = vec3(1.0);
  precise float e = NORMAL_EPS;
  precise vec3 g = a * mapObject(p + a * e, u_morph) + b * mapObject(p + b * e, u_morph) +
                   c * mapObject(p + c * e, u_morph) + d * mapObject(p + d * e, u_morph);
  return g / sqrt(dm_dot(g, g));
}

vec3 to_world(vec3 v) {
  return u_exhibit_to_world0 * v.x + u_exhibit_to_world1 * v.y + u_exhibit_to_world2 * v.z;
}

float hit_eps(float t) {
  precise float e = u_morph.naive != 0 ? u_morph.hit_eps
                                       : dm_max(MIN_EPS, u_morph.hit_eps * u_pixel_angle * t);
  return e;
}

// exhibit_reflection() of the C++: the object itself, or else the hall through the probe.
vec3 exhibit_reflection(vec3 p, vec3 n, vec3 r, float t_hit) {
  precise vec3 ro = p + n * surfaceBias(hit_eps(t_hit));
  precise vec2 span = box_span(ro, r);
  precise float t = dm_max(span.x, 0.0);
  for (int i = 0; i < u_morph.reflect_steps && t < span.y; ++i) {
    precise float d = mapObject(ro + r * t, u_morph);
    if (d < hit_eps(t_hit + t)) {
      precise vec3 nq = object_normal(ro + r * t);
      precise vec3 mirror = sample_probe(to_world(reflectDir(r, nq)));
      return shadeObjectLit(nq, r, mirror, 1.0, 1.0, u_morph);
    }
    t = t + d;
  }
  return sample_probe(to_world(r));
}

void main() {
  precise vec3 to_point = v_world_position - u_camera_origin;
  precise vec3 dir = to_point / sqrt(dm_dot(to_point, to_point));
  precise vec3 o = (u_exhibit_inv_model * vec4(u_camera_origin, 1.0)).xyz;
  precise vec3 dl = (u_exhibit_inv_model * vec4(dir, 0.0)).xyz * u_exhibit_scale;
  precise vec2 span = box_span(o, dl);
  precise float t = dm_max(span.x, 0.0);
  bool hit = false;
  for (int i = 0; i < u_morph.max_steps && t < span.y; ++i) {
    precise float d = mapObject(o + dl * t, u_morph);
    if (d < hit_eps(t)) {
      hit = true;
      break;
    }
    t = t + d;
  }
  if (!hit) discard;
  precise vec3 p = o + dl * t;
  precise vec3 n = object_normal(p);
  precise vec3 world_hit = u_camera_origin + dir * (t * u_exhibit_scale);
  precise vec3 world_n = to_world(n);
  precise float view_depth = dm_dot(world_hit - u_camera_origin, u_camera_forward);
  gl_FragDepth = window_depth(view_depth);
  if (u_morph.surface != SURFACE_COLOUR) {  // the hit's distance from the eye or its normal
    frag_color = vec4(surfaceOutput(u_morph.surface, t * u_exhibit_scale, world_n), 1.0);
    return;
  }
  if (u_morph.hit_mask != 0) {
    frag_color = vec4(1.0);  // sdf_morph's HIT_ID_OBJECT
    return;
  }
  precise vec3 reflection = exhibit_reflection(p, n, reflectDir(dl, n), t);
  precise float ndl = dm_dot(world_n, TO_SUN);
  precise float shadow = ndl > 0.0 ? sun_visibility(world_hit, world_n, ndl) : 0.0;
  frag_color = vec4(shadeObjectLit(n, dl, reflection, shadow, 1.0, u_morph), 1.0);
}
