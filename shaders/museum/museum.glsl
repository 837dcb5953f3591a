// museum: the sky ray pass (what the window shows), the twin of sky_pass() in
// src/scenes/museum/museum.cpp. The hall, the exhibits and the air are other passes of the plan:
// hall.frag, sdf_exhibit.frag, occlusion.glsl, composite.glsl.
#include "common/sample_loop.glsl"
#include "common/surface_output.glsl"
#include "museum/lighting.glsl"

uniform float u_hit_mask;  // 1: the sky's hit id (0) instead of radiance
uniform float u_surface;   // MarchSettings::surface: the sky is no surface

vec3 radiance(Ray ray, inout RayStats stats) {
  if (int(u_surface) != SURFACE_COLOUR) return noSurface(int(u_surface));
  return u_hit_mask > 0.5 ? vec3(0.0) : sky(ray.dir);
}
