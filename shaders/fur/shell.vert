// The vertex stage of a fur shell (src/scenes/fur/shell_shading.cpp, place_shell_vertex): the
// vertex pushed out along its normal by h * length, then the seed's two physics offsets, rotation
// mix(V, R V, k) about the body's centre and translation k * strength * D.
#include "common/frame.glsl"

layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec2 a_uv;
layout(location = 3) in vec4 a_model0;
layout(location = 4) in vec4 a_model1;
layout(location = 5) in vec4 a_model2;
layout(location = 6) in vec4 a_model3;
layout(location = 7) in vec4 a_instance_data;  // h, fake AO, k, shell index

uniform float u_fur_length;
uniform vec3 u_fur_centre;
uniform mat4 u_fur_twist;  // a rotation in its upper 3x3
uniform vec3 u_fur_offset;

out vec3 v_world_position;
out vec3 v_world_normal;
out vec2 v_uv;
flat out vec4 v_instance_data;

void main() {
  mat4 model = mat4(a_model0, a_model1, a_model2, a_model3);
  vec3 world_normal = mat3(model) * a_normal;
  vec3 world = (model * vec4(a_position, 1.0)).xyz;
  world += normalize(world_normal) * (u_fur_length * a_instance_data.x);
  float k = a_instance_data.z;
  vec3 rel = world - u_fur_centre;
  world = u_fur_centre + mix(rel, mat3(u_fur_twist) * rel, k) + u_fur_offset * k;
  v_world_position = world;
  v_world_normal = world_normal;
  v_uv = a_uv;
  v_instance_data = a_instance_data;
  gl_Position = u_projection * (u_view * vec4(world, 1.0));
}
