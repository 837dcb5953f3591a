// What a mesh pass's fragment shader includes: the varyings of common/mesh.vert and the output.
// The shader defines vec4 shade(MeshFragment f), the twin of MeshPass::shade; fragments with
// alpha below u_alpha_cutoff are discarded, as on the CPU.
#include "common/frame.glsl"

in vec3 v_world_position;
in vec3 v_world_normal;
in vec2 v_uv;
flat in vec4 v_instance_data;

uniform float u_alpha_cutoff;

struct MeshFragment {
  vec3 world_position;
  vec3 world_normal;
  vec2 uv;
  vec4 instance_data;
  bool front_facing;
};

vec4 shade(MeshFragment f);

layout(location = 0) out vec4 frag_color;

void main() {
  vec4 c = shade(MeshFragment(v_world_position, v_world_normal, v_uv, v_instance_data,
                              gl_FrontFacing));
  if (c.a < u_alpha_cutoff) discard;
  frag_color = c;
}
