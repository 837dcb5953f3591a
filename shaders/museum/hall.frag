// The hall's boxes (mesh pass "hall" of src/scenes/museum/museum.cpp): instance data is the
// albedo (rgb) and the material code (w) of hall_layout.h.
#include "common/mesh_fragment.glsl"
#include "common/surface_output.glsl"
#include "museum/lighting.glsl"

uniform float u_hit_mask;  // 1: the hall's hit id (2) instead of radiance
uniform float u_surface;   // MarchSettings::surface: the distance from the eye or the normal

vec4 shade(MeshFragment f) {
  if (u_hit_mask > 0.5) return vec4(2.0, 2.0, 2.0, 1.0);
  if (int(u_surface) != SURFACE_COLOUR)
    return vec4(surfaceOutput(int(u_surface), length(f.world_position - u_camera_origin),
                              normalize(f.world_normal)),
                1.0);
  return vec4(hall_radiance(f.world_position, f.world_normal, f.instance_data.rgb,
                            f.instance_data.w),
              1.0);
}
