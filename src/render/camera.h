#pragma once
// Pinhole camera: position/target/fov/roll (+Y up) turned into an orthonormal basis and primary
// rays.
#include <glm/glm.hpp>

namespace sdfreel {

struct CameraPose {
  glm::dvec3 position{0.0, 1.0, -5.0};
  glm::dvec3 target{0.0, 0.0, 0.0};
  double fov_deg = 50.0;  // vertical field of view, in (0, 180)
  double roll_deg = 0.0;  // about the view axis, counter-clockwise as seen by the camera
};

// Right-handed view basis. forward points at the target, up is +Y projected, right = forward x up.
// Looking straight up or down (forward parallel to +Y) uses +Z as the reference up instead, so the
// basis is always defined and finite.
struct CameraBasis {
  glm::vec3 origin;
  glm::vec3 right, up, forward;
  float tan_half_fov;  // tan(fov/2), vertical
};

CameraBasis make_camera_basis(const CameraPose& pose);

// Direction through image position (px, py) in pixels, origin top-left, y down; (w, h) the image
// size.
glm::vec3 primary_ray_dir(const CameraBasis& cam, float px, float py, int w, int h);

}  // namespace sdfreel
