// The vertex stage of mesh passes (src/render/frame_plan.h, MeshPass): model matrix and data per
// instance (attributes 3..7), the camera model's view and sample-moved projection
// (src/render/camera_model.h). Fragment shaders include common/mesh_fragment.glsl.
#include "common/frame.glsl"

layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec2 a_uv;
layout(location = 3) in vec4 a_model0;
layout(location = 4) in vec4 a_model1;
layout(location = 5) in vec4 a_model2;
layout(location = 6) in vec4 a_model3;
layout(location = 7) in vec4 a_instance_data;

out vec3 v_world_position;
out vec3 v_world_normal;
out vec2 v_uv;
flat out vec4 v_instance_data;

void main() {
  mat4 model = mat4(a_model0, a_model1, a_model2, a_model3);
  vec4 world = model * vec4(a_position, 1.0);
  v_world_position = world.xyz;
  v_world_normal = mat3(model) * a_normal;  // models are rotations and uniform scales
  v_uv = a_uv;
  v_instance_data = a_instance_data;
  gl_Position = u_projection * (u_view * world);
}
