// Primary rays and depth: the twins of primary_ray_dir (src/render/camera.cpp) and window_depth
// (src/render/camera_model.cpp).
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

// Window depth of a point at view depth d (src/render/camera_model.h, the depth convention).
float window_depth(float view_depth) {
  return u_depth_scale * (1.0 - u_near_plane / view_depth);
}
