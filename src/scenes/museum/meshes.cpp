#include "scenes/museum/meshes.h"

#include <glm/gtc/matrix_transform.hpp>

namespace sdfreel::museum {

MeshInstance box_instance(const glm::vec3& lo, const glm::vec3& hi, const glm::vec4& data) {
  const glm::mat4 m = glm::scale(glm::translate(glm::mat4(1.0f), (lo + hi) * 0.5f), hi - lo);
  return {m, data};
}

}  // namespace sdfreel::museum
