// The exhibit's physics as a function of TIME: at rest before the first push, in the air after it,
// inside the case at every moment, at rest again later, the same bits whatever was computed
// before, and a bounded number of steps at TIME 1e6.
#include "scenes/fur/physics.h"

#include <gtest/gtest.h>

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
    if (std::memcmp(&x.position, &y.position, sizeof x.position) != 0 || x.yaw != y.yaw ||
        std::memcmp(&x.fur_lag, &y.fur_lag, sizeof x.fur_lag) != 0 || x.fur_twist != y.fur_twist)
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
      const double down = support_down(b.shape, b.scale);
      const double side = support_side(b.shape, b.scale, b.yaw);
      EXPECT_GE(b.position.y, down - tol) << t;
      EXPECT_LE(b.position.y, CASE_HEIGHT - down + tol) << t;
      EXPECT_LE(std::fabs(b.position.x), CASE_HALF_X - side + tol) << t;
      EXPECT_LE(std::fabs(b.position.z), CASE_HALF_Z - side + tol) << t;
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
  EXPECT_GT(p[1].position.y, support_down(p[1].shape, 1.0) + 0.1);  // near the top of its jump
}

TEST(FurPhysics, ThePushAtTheLastMomentIsNotLost) {
  const PhysicsInputs in = pushes(12.0);
  EXPECT_TRUE(same_bits(exhibit_pose(in, 12.0), rest_pose(in, 12.0)));
  EXPECT_FALSE(same_bits(exhibit_pose(in, 12.0 + DT), rest_pose(in, 12.0 + DT)));
}

}  // namespace
}  // namespace sdfreel::fur
