#pragma once
// The exhibit's physics as a pure function of scene TIME: the shapes rest on the case floor until
// the timeline pushes them (up to three pushes, `push_times`), then fall, bounce on the floor and
// on the case walls, knock into each other and come to rest; the fur rides on a damped spring per
// shape (fur/spring.h).
//
// Bodies: semi-implicit Euler at a fixed step DT on a grid that starts at the first push, gravity,
// restitution and friction at contacts. They turn about any axis (an orientation quaternion and an
// angular velocity vector): a push lifts a shape, sends it sideways and sets it tumbling about the
// horizontal axis across its path and spinning about the vertical; on the floor friction slows the
// turn and a shape that lies tilted rights itself (the cube onto its nearest face, the torus flat),
// as gravity about its contact edge would. A push is applied at the first grid step at or after its
// time. A frame at TIME t integrates from the first push to t
// and blends the two grid states around t: the same numbers whatever was rendered before. The cost
// is bounded: a body sleeps when it is slow on the floor, or SLEEP_AFTER seconds after the last
// push at the latest, and the springs snap to rest SETTLE_AFTER seconds after it, after which
// nothing changes until the next push and the loop jumps there. So a frame costs at most
// 3 * SETTLE_AFTER / DT steps, at TIME 1e6 as at TIME 1.
//
// Fur spring, per shape, in exhibit space (x = where the fur tips lag, relative to the body):
//   x'' + 2 zeta omega x' + omega^2 x = g - a_body(t),   g = (0, -9.81, 0) m/s^2,
//   phi'' + 2 zeta omega phi' + omega^2 phi = -alpha_body(t)   (the fur's turn behind the body),
// with a_body and alpha_body the body's (angular) acceleration over each step, constant over the
// step, and each step integrated exactly; phi is a rotation vector (axis times angle), one spring
// per component, so the fur lags a tumble about any axis as seed 004's rotation displacement does.
// At rest x = g / omega^2 (the fur droops by 4 cm times the displacement strength).
#include <array>
#include <cstdint>
#include <glm/glm.hpp>

#include "scenes/fur/shapes.h"

namespace sdfreel::fur {

constexpr double DT = 1.0 / 240.0;
constexpr double SPRING_OMEGA = 2.0 * 3.14159265358979323846 * 2.5;  // 2.5 Hz
constexpr double SPRING_ZETA = 0.3;
constexpr double SLEEP_AFTER = 8.0, SETTLE_AFTER = 12.0;
constexpr double GRAVITY = 9.81;
constexpr int BODY_COUNT = 3;
// The case interior in exhibit space: floor y = 0, walls at x = +-CASE_HALF_X, z = +-CASE_HALF_Z.
constexpr double CASE_HALF_X = 0.78, CASE_HALF_Z = 0.4, CASE_HEIGHT = 0.62;

struct PhysicsInputs {
  std::array<double, 3> push_times{1.5, 6.0, -1.0};  // TIME of each push; negative: none
  double push_strength = 1.0;                        // scales the push's speeds
  double grow_amount = 0.3, grow_period = 6.0;       // the sphere's size: 1 + a sin(2 pi t / T)
};

struct BodyPose {
  Shape shape = Shape::Sphere;
  glm::dvec3 position{0.0};  // centre, exhibit space
  glm::dmat3 turn{1.0};      // orientation: the shape's local axes in exhibit space
  double scale = 1.0;
  glm::dvec3 fur_lag{0.0};    // x of the spring, exhibit space
  glm::dvec3 fur_twist{0.0};  // phi of the spring: a rotation vector, radians
};

using ExhibitPose = std::array<BodyPose, BODY_COUNT>;

// The sphere's scale at TIME t (the other shapes keep scale 1).
double sphere_scale(const PhysicsInputs& in, double t);
// The shapes at rest where they start.
ExhibitPose rest_pose(const PhysicsInputs& in, double t);
// Everything at TIME t; `steps`, when given, receives the number of fixed steps it integrated.
ExhibitPose exhibit_pose(const PhysicsInputs& in, double t, int64_t* steps = nullptr);

}  // namespace sdfreel::fur
