#include "scenes/fur/turning.h"

#include <cmath>

#include "scenes/fur/spring.h"

namespace sdfreel::fur {

glm::dquat rotation_about(const glm::dvec3& axis, double angle) {
  const double s = series_sin(0.5 * angle);
  return glm::dquat(series_cos(0.5 * angle), axis.x * s, axis.y * s, axis.z * s);
}

glm::dmat3 rotation(const glm::dvec3& rotation_vector) {
  const double angle = std::sqrt(glm::dot(rotation_vector, rotation_vector));
  if (!(angle > 0.0)) return glm::dmat3(1.0);
  return glm::mat3_cast(rotation_about(rotation_vector / angle, angle));
}

glm::dvec3 rest_axis(Shape s, const glm::dmat3& turn) {
  if (s == Shape::Sphere) return glm::dvec3(0.0);
  int best = 1;
  if (s == Shape::RoundedCube)
    for (int i = 0; i < 3; ++i)
      if (std::fabs(turn[i].y) > std::fabs(turn[best].y)) best = i;
  return turn[best].y < 0.0 ? -turn[best] : turn[best];
}

glm::dquat flat_turn(const glm::dvec3& axis) {
  const glm::dvec3 c = glm::cross(axis, glm::dvec3(0.0, 1.0, 0.0));
  return glm::dquat(1.0 + axis.y, c.x, c.y, c.z);
}

}  // namespace sdfreel::fur
