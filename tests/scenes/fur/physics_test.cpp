// The exhibit's physics as a function of TIME: at rest before the first push, in the air after it,
// inside the case at every moment, at rest again later, the same bits whatever was computed
// before, and a bounded number of steps at TIME 1e6. Shapes tumble about horizontal axes, the fur
// lags the tumble, and they come to rest lying flat.
#include "scenes/fur/physics.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>

namespace sdfreel::fur {
namespace {

PhysicsInputs pushes(double a, double b = -1.0, double c = -1.0) {
  PhysicsInputs in;
  in.push_times = {a, b, c};
  return in;
}

bool same_bits(const ExhibitPose& a, const ExhibitPose& b) {
  for (int i = 0; i < BODY_COUNT; ++i) {
    const BodyPose &x = a[size_t(i)], &y = b[size_t(i)];
    if (std::memcmp(&x.position, &y.position, sizeof x.position) != 0 ||
        std::memcmp(&x.turn, &y.turn, sizeof x.turn) != 0 ||
        std::memcmp(&x.fur_lag, &y.fur_lag, sizeof x.fur_lag) != 0 ||
        std::memcmp(&x.fur_twist, &y.fur_twist, sizeof x.fur_twist) != 0)
      return false;
  }
  return true;
}

TEST(FurPhysics, RestBeforeThePushAndInTheAirAfterIt) {
  const PhysicsInputs in = pushes(2.0);
  EXPECT_TRUE(same_bits(exhibit_pose(in, 1.9), rest_pose(in, 1.9)));
  EXPECT_TRUE(same_bits(exhibit_pose(in, 2.0), rest_pose(in, 2.0)));  // a push at t acts after t
  const ExhibitPose rest = rest_pose(in, 2.2), air = exhibit_pose(in, 2.2);
  for (int i = 0; i < BODY_COUNT; ++i)
    EXPECT_GT(air[size_t(i)].position.y, rest[size_t(i)].position.y + 0.1) << i;
}

TEST(FurPhysics, ShapesStayInsideTheCaseAndComeToRest) {
  PhysicsInputs in = pushes(0.0, 0.6, 1.1);
  in.push_strength = 3.0;  // hard pushes: the shapes hit the walls and the glass lid
  // Between two steps a pose is blended while the sphere's size is that of TIME: the sphere grows
  // by less than 1e-3 in a step.
  const double tol = 1e-3;
  for (double t = 0.0; t < 14.0; t += 0.05) {
    const ExhibitPose p = exhibit_pose(in, t);
    for (const BodyPose& b : p) {
      const double down = support(b.shape, b.scale, b.turn, 1);
      EXPECT_GE(b.position.y, down - tol) << t;
      EXPECT_LE(b.position.y, CASE_HEIGHT - down + tol) << t;
      EXPECT_LE(std::fabs(b.position.x), CASE_HALF_X - support(b.shape, b.scale, b.turn, 0) + tol)
          << t;
      EXPECT_LE(std::fabs(b.position.z), CASE_HALF_Z - support(b.shape, b.scale, b.turn, 2) + tol)
          << t;
    }
  }
  // SETTLE_AFTER seconds after the last push nothing moves any more (the sphere's size aside).
  in.grow_amount = 0.0;
  const double settled = 1.1 + SETTLE_AFTER + 0.1;
  EXPECT_TRUE(same_bits(exhibit_pose(in, settled), exhibit_pose(in, settled + 50.0)));
  const ExhibitPose moved = exhibit_pose(in, settled), start = rest_pose(in, settled);
  EXPECT_FALSE(same_bits(moved, start)) << "the pushes should have moved the shapes somewhere";
}

TEST(FurPhysics, APoseDependsOnlyOnItsTime) {
  const PhysicsInputs in = pushes(0.5, 3.0);
  const ExhibitPose alone = exhibit_pose(in, 3.37);
  for (double t = 0.0; t < 3.37; t += 0.31) exhibit_pose(in, t);
  EXPECT_TRUE(same_bits(exhibit_pose(in, 3.37), alone));
}

TEST(FurPhysics, HugeTimeCostsBoundedSteps) {
  const PhysicsInputs in = pushes(0.0, 5e5, 1e6 - 0.25);
  int64_t steps = 0;
  const ExhibitPose p = exhibit_pose(in, 1e6, &steps);
  EXPECT_LE(steps, int64_t(3 * SETTLE_AFTER / DT) + 2);
  EXPECT_GT(steps, int64_t(0.2 / DT));  // the last push is really integrated
  for (const BodyPose& b : p) EXPECT_TRUE(std::isfinite(b.position.y));
  EXPECT_GT(p[1].position.y, support(p[1].shape, 1.0, p[1].turn, 1) + 0.1);  // near its jump's top
}

TEST(FurPhysics, ThePushAtTheLastMomentIsNotLost) {
  const PhysicsInputs in = pushes(12.0);
  EXPECT_TRUE(same_bits(exhibit_pose(in, 12.0), rest_pose(in, 12.0)));
  EXPECT_FALSE(same_bits(exhibit_pose(in, 12.0 + DT), rest_pose(in, 12.0 + DT)));
}

// How far the shape's local up axis leans from the vertical, radians.
double tilt(const BodyPose& b) {
  return std::acos(std::clamp(b.turn[1].y, -1.0, 1.0));
}

// Seed 004 turns its shapes any way (its example: a roll towards the viewer); a push tumbles them
// about horizontal axes, and the fur's turn behind the body (a rotation vector) follows about such
// an axis too.
TEST(FurPhysics, APushTumblesTheShapesAndTheFurLagsTheTumble) {
  const PhysicsInputs in = pushes(1.5, 6.0);
  double most_tilt[BODY_COUNT] = {}, fur_across = 0.0;
  for (double t = 1.5; t < 4.0; t += 0.02) {
    const ExhibitPose p = exhibit_pose(in, t);
    for (int i = 0; i < BODY_COUNT; ++i) {
      most_tilt[i] = std::max(most_tilt[i], tilt(p[size_t(i)]));
      const glm::dvec3 twist = p[size_t(i)].fur_twist;
      fur_across = std::max(fur_across, std::sqrt(twist.x * twist.x + twist.z * twist.z));
    }
  }
  for (int i = 0; i < BODY_COUNT; ++i) EXPECT_GT(most_tilt[i], 0.35) << i << ": 20 degrees";
  EXPECT_GT(fur_across, 0.05) << "the fur turns behind a tumble, about a horizontal axis";
}

TEST(FurPhysics, TumbledShapesComeToRestLyingFlat) {
  PhysicsInputs in = pushes(0.0, 0.6, 1.1);
  in.push_strength = 3.0;
  in.grow_amount = 0.0;
  const ExhibitPose p = exhibit_pose(in, 1.1 + SETTLE_AFTER + 0.1);
  for (const BodyPose& b : p) {
    EXPECT_NEAR(b.position.y, support(b.shape, b.scale, b.turn, 1), 1e-6);  // on the floor
    if (b.shape == Shape::Sphere) continue;
    // The torus lies on its side, the cube on a face: one local axis straight up.
    double up = 0.0;
    for (int k = 0; k < 3; ++k)
      if (b.shape == Shape::RoundedCube || k == 1) up = std::max(up, std::fabs(b.turn[k].y));
    EXPECT_NEAR(up, 1.0, 1e-9) << int(b.shape);
  }
}

}  // namespace
}  // namespace sdfreel::fur
