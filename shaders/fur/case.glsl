// The exhibit case and the room (src/scenes/fur/case_shading.cpp, shade_case): Lambert from the
// key light, ambient, soft contact shadows under the three shapes.
#include "common/mesh_fragment.glsl"
#include "common/surface_output.glsl"

uniform vec3 u_light_dir;
uniform vec3 u_light;
uniform vec3 u_ambient;
uniform vec4 u_bodies[3];  // world centre, footprint radius
uniform float u_hit_mask;  // 1: draw hit id 0 (MarchSettings::hit_mask)
uniform float u_surface;  // MarchSettings::surface: the distance from the eye or the normal

vec4 shade(MeshFragment f) {
  if (u_hit_mask > 0.5) return vec4(0.0, 0.0, 0.0, 1.0);
  vec3 n = normalize(f.world_normal);
  if (int(u_surface) != SURFACE_COLOUR)
    return vec4(surfaceOutput(int(u_surface), length(f.world_position - u_camera_origin), n), 1.0);
  float lambert = dm_max(dot(n, u_light_dir), 0.0);
  float shadow = 1.0;
  for (int i = 0; i < 3; ++i) {
    vec4 b = u_bodies[i];
    vec2 d = vec2(f.world_position.x - b.x, f.world_position.z - b.z);
    float across = length(d) / (b.w * 1.3);
    float above = (b.y - f.world_position.y) / b.w;
    float a = dm_clamp(1.0 - across, 0.0, 1.0) * dm_clamp(1.6 - 0.3 * above, 0.0, 1.0);
    shadow *= 1.0 - 0.6 * a * a * dm_clamp(n.y, 0.0, 1.0);
  }
  return vec4(f.instance_data.rgb * (u_light * lambert + u_ambient) * shadow, 1.0);
}
