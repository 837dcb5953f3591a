#include "render/camera.h"

#include <gtest/gtest.h>

#include <cmath>

namespace sdfreel {
namespace {

void expect_orthonormal(const CameraBasis& b) {
  for (const glm::vec3& v : {b.right, b.up, b.forward}) {
    EXPECT_TRUE(std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z));
    EXPECT_NEAR(glm::length(v), 1.0f, 1e-5f);
  }
  EXPECT_NEAR(glm::dot(b.right, b.up), 0.0f, 1e-5f);
  EXPECT_NEAR(glm::dot(b.right, b.forward), 0.0f, 1e-5f);
  EXPECT_NEAR(glm::dot(b.up, b.forward), 0.0f, 1e-5f);
  // Right-handed view: right x up = -forward is not required; right = forward x up must hold.
  const glm::vec3 r = glm::cross(b.forward, b.up);
  EXPECT_NEAR(glm::length(r - b.right), 0.0f, 1e-5f);
}

TEST(Camera, LevelCameraHasYUpAndForwardToTarget) {
  const CameraBasis b = make_camera_basis({{0, 1, -5}, {0, 1, 0}, 60.0, 0.0});
  expect_orthonormal(b);
  EXPECT_NEAR(b.forward.z, 1.0f, 1e-6f);
  EXPECT_NEAR(b.up.y, 1.0f, 1e-6f);
  EXPECT_NEAR(b.tan_half_fov, std::tan(30.0 * M_PI / 180.0), 1e-6);
}

TEST(Camera, StraightDownAndStraightUpAreDefined) {
  const CameraBasis down = make_camera_basis({{0, 10, 0}, {0, 0, 0}, 50.0, 0.0});
  expect_orthonormal(down);
  EXPECT_NEAR(down.forward.y, -1.0f, 1e-6f);
  EXPECT_NEAR(down.up.z, 1.0f, 1e-6f);  // image-up points along +Z when looking down
  const CameraBasis up = make_camera_basis({{0, 0, 0}, {0, 10, 0}, 50.0, 0.0});
  expect_orthonormal(up);
  EXPECT_NEAR(up.forward.y, 1.0f, 1e-6f);
  EXPECT_NEAR(up.up.z, -1.0f, 1e-6f);
}

TEST(Camera, NearlyStraightDownIsContinuousWithStraightDown) {
  const CameraBasis exact = make_camera_basis({{0, 10, 0}, {0, 0, 0}, 50.0, 0.0});
  const CameraBasis tilted = make_camera_basis({{0, 10, 0}, {0, 0, 1e-3}, 50.0, 0.0});
  EXPECT_NEAR(glm::length(exact.up - tilted.up), 0.0f, 1e-3f);
  EXPECT_NEAR(glm::length(exact.right - tilted.right), 0.0f, 1e-3f);
}

TEST(Camera, RollRotatesRightTowardsUp) {
  const CameraBasis b = make_camera_basis({{0, 1, -5}, {0, 1, 0}, 60.0, 90.0});
  expect_orthonormal(b);
  EXPECT_NEAR(b.right.y, 1.0f, 1e-6f);
}

TEST(Camera, CentreRayIsForwardAndCornersAreSymmetric) {
  const CameraBasis b = make_camera_basis({{1, 2, 3}, {4, 0, 7}, 45.0, 10.0});
  const glm::vec3 c = primary_ray_dir(b, 32.0f, 18.0f, 64, 36);
  EXPECT_NEAR(glm::length(c - b.forward), 0.0f, 1e-6f);
  const glm::vec3 tl = primary_ray_dir(b, 0.0f, 0.0f, 64, 36);
  const glm::vec3 br = primary_ray_dir(b, 64.0f, 36.0f, 64, 36);
  EXPECT_NEAR(glm::dot(tl, b.up), -glm::dot(br, b.up), 1e-6f);
  EXPECT_GT(glm::dot(tl, b.up), 0.0f);  // row 0 is the top of the image
  // The vertical half-angle matches the fov.
  const glm::vec3 top = primary_ray_dir(b, 32.0f, 0.0f, 64, 36);
  EXPECT_NEAR(std::acos(glm::dot(top, b.forward)) * 180.0 / M_PI, 22.5, 1e-3);
}

}  // namespace
}  // namespace sdfreel
