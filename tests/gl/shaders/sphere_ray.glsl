// The ray-marched sphere of tests/gl/mixed_plan.cpp (its C++ twin, same operations).
#include "common/ray_pass_depth.glsl"

const vec3 SPHERE_CENTRE = vec3(0.6, 0.7, 0.3);
const float SPHERE_RADIUS = 0.7;
const vec3 SPHERE_ALBEDO = vec3(0.9, 0.35, 0.2);
const vec3 LIGHT_DIR = vec3(0.48, 0.8, -0.36);
const int MAX_STEPS = 96;
const float HIT_EPS = 1e-4;
const float MAX_T = 40.0;

bool shade_ray(Ray ray, inout RayStats stats, out vec3 colour, out float view_depth) {
  precise float t = 0.0;
  for (int i = 0; i < MAX_STEPS; ++i) {
    precise vec3 p = ray.origin + ray.dir * t;
    precise float d = dm_length(p - SPHERE_CENTRE) - SPHERE_RADIUS;
    stats.sdf_evals += 1u;
    if (d < HIT_EPS) {
      precise vec3 n = (p - SPHERE_CENTRE) / SPHERE_RADIUS;
      precise float lambert = dm_max(dm_dot(n, LIGHT_DIR), 0.0);
      colour = SPHERE_ALBEDO * (0.2 + 0.8 * lambert);
      view_depth = t * dm_dot(ray.dir, u_camera_forward);
      return true;
    }
    t = t + d;
    if (t > MAX_T) break;
  }
  colour = vec3(0.0);
  view_depth = 0.0;
  return false;
}
