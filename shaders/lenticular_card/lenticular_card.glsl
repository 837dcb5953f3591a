// lenticular_card's one pass (src/scenes/lenticular_card/lenticular_card.cpp, frame_plan): the
// card over the backdrop, the twin of backdrop.cpp below the card.glsl that card_pass.glsl (the
// museum's exhibit) shares.
#include "common/sample_loop.glsl"
#include "common/surface_output.glsl"
#include "lenticular_card/card.glsl"

uniform vec3 u_backdrop_light;
uniform int u_backdrop_hit_mask;  // MarchSettings::hit_mask: nothing marched here, id 0
uniform int u_backdrop_surface;   // MarchSettings::surface: the floor, nothing above the horizon

const vec3 FLOOR = vec3(0.30, 0.27, 0.24), WALL_LOW = vec3(0.06, 0.06, 0.07);
const vec3 WALL_HIGH = vec3(0.015, 0.018, 0.025);
const float FLOOR_FADE = 4.0;
const float SHADOW_RADIUS = 0.35;
const float SHADOW_DEPTH = 0.55;

vec3 backdrop(Ray ray) {
  if (u_backdrop_hit_mask != 0) return vec3(0.0);
  if (u_backdrop_surface != SURFACE_COLOUR) {
    if (!(ray.dir.y < 0.0) || !(ray.origin.y > 0.0)) return noSurface(u_backdrop_surface);
    precise float t = -ray.origin.y / ray.dir.y;
    return surfaceOutput(u_backdrop_surface, t, vec3(0.0, 1.0, 0.0));
  }
  precise vec3 wall = dm_mix(WALL_LOW, WALL_HIGH, dm_smoothstep(-0.1, 0.6, ray.dir.y));
  if (!(ray.dir.y < 0.0) || !(ray.origin.y > 0.0)) return wall;
  precise float t = -ray.origin.y / ray.dir.y;
  precise float x = ray.origin.x + ray.dir.x * t, z = ray.origin.z + ray.dir.z * t;
  precise float r = sqrt(x * x + z * z);
  precise float shadow = 1.0 - SHADOW_DEPTH * (1.0 - dm_smoothstep(0.0, SHADOW_RADIUS, r));
  precise vec3 lit = FLOOR * ((0.3 + 0.9 * dm_max(u_backdrop_light.y, 0.0)) * shadow);
  precise vec3 c = dm_mix(lit, wall, dm_smoothstep(0.0, FLOOR_FADE, r));
  return c;
}

// The card where its own pass would pass the depth test (LESS against the cleared depth, 1),
// else the backdrop: what the card's pass over the backdrop's drew.
vec3 radiance(Ray ray, inout RayStats stats) {
  precise vec3 colour;
  precise float t;
  if (shadeCard(ray, colour, t)) {
    precise float view_depth = t * (ray.dir.x * u_camera_forward.x +
                                    ray.dir.y * u_camera_forward.y +
                                    ray.dir.z * u_camera_forward.z);
    if (window_depth(view_depth) < 1.0) return colour;
  }
  return backdrop(ray);
}
