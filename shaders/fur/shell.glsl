// A fur shell's fragment (src/scenes/fur/shell_shading.cpp, shade_shell): one strand per UV cell,
// tapering from thickness * rand at the root to nothing at height rand, the innermost shell opaque;
// the seed's half-Lambert and a fake AO constant per shell.
#include "common/mesh_fragment.glsl"
#include "common/surface_output.glsl"
#include "fur/strand_hash.glsl"

const float STRAND_MIN = 0.35;
const float STRAND_MAX = 1.0;

uniform float u_fur_density;
uniform float u_fur_thickness;
uniform vec3 u_fur_base;
uniform vec3 u_fur_tip;
uniform vec3 u_light_dir;
uniform vec3 u_light;
uniform vec3 u_ambient;
uniform float u_hit_id;  // >= 0: draw this id instead (MarchSettings::hit_mask)
uniform float u_surface;  // MarchSettings::surface: the distance from the eye or the normal

vec4 shade(MeshFragment f) {
  float h = f.instance_data.x;
  float ao = f.instance_data.y;
  vec2 uvd = f.uv * u_fur_density;
  vec2 cell = floor(uvd);
  vec2 local = (uvd - cell) * 2.0 - 1.0;
  float rnd = dm_mix(STRAND_MIN, STRAND_MAX, strand_random(ivec2(cell)));
  if (h > 0.0 && length(local) > u_fur_thickness * (rnd - h)) return vec4(0.0);
  if (u_hit_id >= 0.0) return vec4(vec3(u_hit_id), 1.0);
  vec3 n = normalize(f.world_normal);
  if (int(u_surface) != SURFACE_COLOUR)
    return vec4(surfaceOutput(int(u_surface), length(f.world_position - u_camera_origin), n), 1.0);
  float lit = dm_clamp(dot(n, u_light_dir), 0.0, 1.0) * 0.5 + 0.5;
  lit = lit * lit;
  vec3 albedo = dm_mix(u_fur_base, u_fur_tip, h);
  return vec4(albedo * (u_light * lit + u_ambient) * ao, 1.0);
}
