#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "timeline/timeline.h"

namespace sdfreel {
namespace {

CameraKey key(double t, glm::dvec3 position, glm::dvec3 target, double fov = 50, double roll = 0) {
  return CameraKey{t, CameraPose{position, target, fov, roll}};
}

TEST(CameraPath, NoKeysGivesTheFallback) {
  CameraPath path;
  CameraPose fallback{{1, 2, 3}, {4, 5, 6}, 33, 7};
  CameraPose p = path.sample(2.0, fallback);
  EXPECT_EQ(p.position, fallback.position);
  EXPECT_EQ(p.target, fallback.target);
  EXPECT_EQ(p.fov_deg, 33);
  EXPECT_EQ(p.roll_deg, 7);
}

TEST(CameraPath, InterpolatesEveryFieldWithThePathMode) {
  CameraPath path;
  path.interp = Interp::Linear;
  path.keys = {key(0, {0, 0, 0}, {0, 0, 10}, 40, 0), key(2, {4, 2, 0}, {0, 4, 10}, 60, 90)};
  CameraPose p = path.sample(0.5, {});
  EXPECT_DOUBLE_EQ(p.position.x, 1.0);
  EXPECT_DOUBLE_EQ(p.position.y, 0.5);
  EXPECT_DOUBLE_EQ(p.target.y, 1.0);
  EXPECT_DOUBLE_EQ(p.fov_deg, 45.0);
  EXPECT_DOUBLE_EQ(p.roll_deg, 22.5);

  path.interp = Interp::Step;
  EXPECT_EQ(path.sample(1.9, {}).fov_deg, 40);
  // Outside the keys the end poses hold.
  EXPECT_EQ(path.sample(-1, {}).position, glm::dvec3(0, 0, 0));
  EXPECT_EQ(path.sample(5, {}).position, glm::dvec3(4, 2, 0));
}

TEST(CameraPath, KeysSpeedReachesEachKeyAtItsTime) {
  CameraPath path;  // catmull-rom by default
  path.keys = {key(0, {0, 0, 0}, {0, 0, 1}), key(1, {3, 1, 0}, {0, 0, 1}),
               key(4, {5, 0, 2}, {0, 0, 1})};
  for (const CameraKey& k : path.keys) EXPECT_EQ(path.sample(k.t, {}).position, k.pose.position);
}

// Path length covered in each of `steps` equal time steps, measured with `sub` chords per step
// (chords alone would undercount the curved parts).
std::vector<double> step_lengths(const CameraPath& path, double t0, double t1, int steps,
                                 int sub = 1) {
  std::vector<double> out;
  glm::dvec3 prev = path.sample(t0, {}).position;
  for (int i = 0; i < steps; ++i) {
    double length = 0;
    for (int j = 1; j <= sub; ++j) {
      glm::dvec3 p = path.sample(t0 + (t1 - t0) * (i + double(j) / sub) / steps, {}).position;
      length += glm::distance(prev, p);
      prev = p;
    }
    out.push_back(length);
  }
  return out;
}

TEST(CameraPath, ConstantSpeedSpacesAStraightPathEvenly) {
  CameraPath path;
  path.interp = Interp::Linear;
  path.constant_speed = true;
  // 1 unit in the first second, 9 in the next: "keys" speed would jump from 1 to 9 units/s.
  path.keys = {key(0, {0, 0, 0}, {0, 1, 0}), key(1, {1, 0, 0}, {0, 1, 1}),
               key(2, {10, 0, 0}, {0, 1, 2})};
  for (double d : step_lengths(path, 0, 2, 20)) EXPECT_NEAR(d, 0.5, 1e-9);
  // Half way in time is half way along the path, and the target follows the same re-timed
  // parameter: x = 5 is reached at key time 1 + 4/9.
  CameraPose mid = path.sample(1.0, {});
  EXPECT_NEAR(mid.position.x, 5.0, 1e-9);
  EXPECT_NEAR(mid.target.z, 1.0 + 4.0 / 9.0, 1e-9);
  // The ends are still the end keys.
  EXPECT_EQ(path.sample(0, {}).position, glm::dvec3(0, 0, 0));
  EXPECT_EQ(path.sample(2, {}).position, glm::dvec3(10, 0, 0));
}

TEST(CameraPath, ConstantSpeedSpacesACurvedPathEvenly) {
  CameraPath path;
  path.constant_speed = true;
  path.keys = {key(0, {0, 0, 0}, {0, 0, 5}), key(0.5, {2, 1, 0}, {0, 0, 5}),
               key(3, {4, 0, 3}, {0, 0, 5}), key(3.2, {0, 2, 6}, {0, 0, 5})};
  std::vector<double> d = step_lengths(path, 0, 3.2, 32, 8);
  double mean = 0;
  for (double x : d) mean += x / d.size();
  for (double x : d) EXPECT_NEAR(x, mean, 1e-3 * mean);

  // The same keys without constant speed are far from even: the test above can fail.
  path.constant_speed = false;
  std::vector<double> uneven = step_lengths(path, 0, 3.2, 32, 8);
  EXPECT_GT(*std::max_element(uneven.begin(), uneven.end()),
            2 * *std::min_element(uneven.begin(), uneven.end()));
}

TEST(CameraPath, ConstantSpeedWithAStillCameraFollowsKeyTimes) {
  CameraPath path;
  path.interp = Interp::Linear;
  path.constant_speed = true;
  path.keys = {key(0, {1, 1, 1}, {0, 0, 0}, 30), key(2, {1, 1, 1}, {0, 0, 0}, 60)};
  CameraPose p = path.sample(0.5, {});
  EXPECT_EQ(p.position, glm::dvec3(1, 1, 1));
  EXPECT_DOUBLE_EQ(p.fov_deg, 37.5);
}

}  // namespace
}  // namespace sdfreel
