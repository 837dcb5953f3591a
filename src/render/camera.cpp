#include "render/camera.h"

#include <cmath>

namespace sdfreel {

// Per-frame set-up in double: it runs once per frame, not per ray, and both backends receive the
// resulting float basis, so libm here cannot make the backends disagree.
CameraBasis make_camera_basis(const CameraPose& pose) {
  glm::dvec3 forward = pose.target - pose.position;
  const double len = glm::length(forward);
  forward = len > 0.0 ? forward / len : glm::dvec3(0.0, 0.0, 1.0);
  // +Y is the world up. Looking (nearly) straight up or down, +Y and forward are parallel and the
  // cross product vanishes: use +Z as the reference instead, so image-up points along +Z when
  // looking down and along -Z when looking up (continuous with a slightly tilted camera).
  // Guarded by tests/hard_cases/lantern_festival/look_straight_up and
  // sdf_morph/look_straight_down.
  glm::dvec3 ref_up(0.0, 1.0, 0.0);
  if (std::abs(forward.y) > 0.999999) ref_up = glm::dvec3(0.0, 0.0, forward.y > 0.0 ? -1.0 : 1.0);
  glm::dvec3 right = glm::normalize(glm::cross(forward, ref_up));
  glm::dvec3 up = glm::cross(right, forward);
  const double roll = pose.roll_deg * (M_PI / 180.0);
  const double c = std::cos(roll), s = std::sin(roll);
  const glm::dvec3 r2 = right * c + up * s;
  const glm::dvec3 u2 = up * c - right * s;
  CameraBasis b;
  b.origin = glm::vec3(pose.position);
  b.right = glm::vec3(r2);
  b.up = glm::vec3(u2);
  b.forward = glm::vec3(forward);
  b.tan_half_fov = float(std::tan(pose.fov_deg * (M_PI / 360.0)));
  return b;
}

glm::vec3 primary_ray_dir(const CameraBasis& cam, float px, float py, int w, int h) {
  // Screen coordinates: y in [-1, 1] top to bottom flipped, x scaled by the aspect ratio.
  const float sx = (2.0f * px - float(w)) / float(h);
  const float sy = (float(h) - 2.0f * py) / float(h);
  glm::vec3 d =
      cam.forward + cam.right * (sx * cam.tan_half_fov) + cam.up * (sy * cam.tan_half_fov);
  return d / std::sqrt(glm::dot(d, d));
}

}  // namespace sdfreel
