// The lenticular card's ray pass (src/scenes/lenticular_card/exhibit.cpp): the card and its
// stand, depth tested and written, discarded where the ray misses them.
#include "common/ray_pass_depth.glsl"
#include "lenticular_card/card.glsl"

bool shade_ray(Ray ray, inout RayStats stats, out vec3 colour, out float view_depth) {
  precise float t;
  view_depth = 1.0;
  if (!shadeCard(ray, colour, t)) return false;
  view_depth = t * (ray.dir.x * u_camera_forward.x + ray.dir.y * u_camera_forward.y +
                    ray.dir.z * u_camera_forward.z);
  return true;
}
