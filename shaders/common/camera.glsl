// Primary rays: the twin of primary_ray_dir in src/render/camera.cpp.
#include "common/frame.glsl"

// Direction through image position (px, py) in pixels, origin top-left, y down.
vec3 primary_ray_dir(float px, float py) {
  precise float w = float(u_resolution.x), h = float(u_resolution.y);
  precise float sx = (2.0 * px - w) / h;
  precise float sy = (h - 2.0 * py) / h;
  precise vec3 d = u_camera_forward + u_camera_right * (sx * u_tan_half_fov) +
           u_camera_up * (sy * u_tan_half_fov);
  return d / sqrt(dm_dot(d, d));
}
