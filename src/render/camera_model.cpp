#include "render/camera_model.h"

namespace sdfreel {

CameraModel make_camera_model(const CameraBasis& b, int width, int height, float near_plane,
                              float far_plane) {
  const glm::dvec3 r(b.right), u(b.up), f(b.forward), o(b.origin);
  glm::dmat4 view(1.0);
  for (int c = 0; c < 3; ++c) {  // rows right, up, -forward: view[column][row]
    view[c][0] = r[c];
    view[c][1] = u[c];
    view[c][2] = -f[c];
  }
  view[3] = glm::dvec4(-glm::dot(r, o), -glm::dot(u, o), glm::dot(f, o), 1.0);
  const double n = near_plane, fa = far_plane, t = b.tan_half_fov;
  const double aspect = double(width) / double(height);
  glm::dmat4 proj(0.0);
  proj[0][0] = 1.0 / (aspect * t);
  proj[1][1] = 1.0 / t;
  proj[2][2] = -(fa + n) / (fa - n);
  proj[2][3] = -1.0;
  proj[3][2] = -2.0 * fa * n / (fa - n);
  CameraModel cam;
  cam.view = glm::mat4(view);
  cam.projection = glm::mat4(proj);
  cam.near_plane = near_plane;
  cam.far_plane = far_plane;
  cam.depth_scale = float(fa / (fa - n));
  return cam;
}

glm::mat4 sample_projection(const CameraModel& cam, glm::vec2 offset, int width, int height) {
  // Window x grows with image x; window y = height - image y. Moving the image by (0.5 - o.x,
  // -(0.5 - o.y)) window pixels puts image position (x + o) on the centre of pixel (x, y).
  const double dx = 2.0 * (0.5 - double(offset.x)) / double(width);
  const double dy = -2.0 * (0.5 - double(offset.y)) / double(height);
  glm::dmat4 shift(1.0);  // NDC translation after the divide: clip.xy += (dx, dy) * clip.w
  shift[3][0] = dx;
  shift[3][1] = dy;
  return glm::mat4(shift * glm::dmat4(cam.projection));
}

float window_depth(const CameraModel& cam, float view_depth) {
  return cam.depth_scale * (1.0f - cam.near_plane / view_depth);
}

float view_depth(const CameraModel& cam, float window_depth) {
  return cam.near_plane / (1.0f - window_depth / cam.depth_scale);
}

}  // namespace sdfreel
