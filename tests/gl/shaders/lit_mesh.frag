// The cubes of tests/gl/mixed_plan.cpp: instance colour, one directional light.
#include "common/mesh_fragment.glsl"

const vec3 LIGHT_DIR = vec3(0.48, 0.8, -0.36);

vec4 shade(MeshFragment f) {
  vec3 n = normalize(f.world_normal);
  float lambert = max(dot(n, LIGHT_DIR), 0.0);
  return vec4(f.instance_data.rgb * (0.2 + 0.8 * lambert), 1.0);
}
