#pragma once
// One camera model for every pass kind: ray passes trace rays through the image positions that
// mesh passes project to, and both write the same depth for the same point.
//
// DEPTH CONVENTION (both backends, every pass kind; docs/architecture.md, "Frames as passes"):
// - View space is right-handed: the eye at the origin looking down -Z, +X right, +Y up; the rows
//   of the view matrix are CameraBasis right, up and -forward.
// - The projection is OpenGL's perspective (vertical field of view of the pose, aspect
//   width / height, near n and far f of the frame plan), NDC z in [-1, 1] (GL's default clip
//   control), image x to the right and image y down as in primary_ray_dir.
// - Depth targets hold window depth z_w = 0.5 * z_ndc + 0.5 in [0, 1]: 0 on the near plane, 1 on
//   the far plane and where nothing was drawn (depth targets are cleared to 1); a LESS test keeps
//   the nearer surface. For a point at view depth d = -z_view (distance along forward, not along
//   the ray): z_w = f / (f - n) * (1 - n / d). A ray hit at distance t along a unit ray has
//   d = t * dot(dir, forward).
// - Mesh passes get z_w by rasterising clip = projection * view * model * p; ray passes compute it
//   with window_depth(). The two agree to float rounding (tests/render/camera_model_test.cpp).
#include <glm/glm.hpp>

#include "render/camera.h"

namespace sdfreel {

struct CameraModel {
  glm::mat4 view{1.0f}, projection{1.0f};  // column-major, as GLSL takes them
  float near_plane = 0.05f, far_plane = 500.0f;
  float depth_scale = 1.0f;  // f / (f - n), in float, as both backends use it
};

// View and projection of `basis` for a width x height image (computed in double, rounded once).
CameraModel make_camera_model(const CameraBasis& basis, int width, int height, float near_plane,
                              float far_plane);

// The projection moved so that the pixel centre (x + 0.5, y + 0.5), where GL rasterises, shows the
// image position (x + offset.x, y + offset.y) that a ray pass traces for sub-pixel sample
// `offset`: meshes and rays are sampled at the same positions.
glm::mat4 sample_projection(const CameraModel& cam, glm::vec2 offset, int width, int height);

// z_w of a point at view depth d > 0 (the convention above). Float, in the written order; the
// GLSL twin is window_depth() in shaders/common/camera.glsl.
float window_depth(const CameraModel& cam, float view_depth);
// The inverse: view depth of window depth z_w in [0, 1).
float view_depth(const CameraModel& cam, float window_depth);

}  // namespace sdfreel
