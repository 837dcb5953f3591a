// Scene "fur" (src/scenes/fur/fur.cpp): the background ray pass; the room, the case and the furry
// shapes are mesh passes (fur/case.glsl, fur/shell.vert, fur/shell.glsl).
#include "common/sample_loop.glsl"
#include "common/surface_output.glsl"

uniform float u_hit_mask;  // 1: hit id 0 (MarchSettings::hit_mask)
uniform float u_surface;   // MarchSettings::surface: the background is no surface

vec3 radiance(Ray ray, inout RayStats stats) {
  if (int(u_surface) != SURFACE_COLOUR) return noSurface(int(u_surface));
  if (u_hit_mask > 0.5) return vec3(0.0);
  return vec3(0.018, 0.02, 0.025);
}
