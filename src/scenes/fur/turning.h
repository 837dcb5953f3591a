#pragma once
// Turning the exhibit's bodies without libm (so every machine gets the same bits): rotations from
// the power series of fur/spring.h, the axis a shape comes to rest on, and the turn that lays it
// flat. Used by the physics (fur/physics.h) and the shells' rotation displacement (fur/exhibit.h).
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "scenes/fur/shapes.h"

namespace sdfreel::fur {

// The rotation by `angle` about the unit `axis` (|angle| < 4).
glm::dquat rotation_about(const glm::dvec3& axis, double angle);
// The rotation by a rotation vector (axis times angle, |angle| < 4).
glm::dmat3 rotation(const glm::dvec3& rotation_vector);

// The axis that points up when a shape turned by `turn` lies still, signed upwards: the cube's
// local axis nearest the vertical, the torus' own axis; zero for the sphere, which lies still any
// way.
glm::dvec3 rest_axis(Shape s, const glm::dmat3& turn);
// The turn that takes `axis` (a rest axis, pointing up or level) straight up: the half-way
// quaternion from it to +y.
glm::dquat flat_turn(const glm::dvec3& axis);

}  // namespace sdfreel::fur
