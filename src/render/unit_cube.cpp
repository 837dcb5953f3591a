#include "render/unit_cube.h"

#include <cmath>
#include <glm/glm.hpp>

namespace sdfreel {
namespace {

std::shared_ptr<TriangleMesh> make_cube() {
  auto m = std::make_shared<TriangleMesh>();
  const glm::vec3 normals[6] = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
                                {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};
  for (const glm::vec3& n : normals) {
    const glm::vec3 u = std::abs(n.y) > 0.5f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
    const glm::vec3 v = glm::cross(n, u);
    const unsigned base = unsigned(m->positions.size() / 3);
    for (const glm::vec2 c :
         {glm::vec2(-1, -1), glm::vec2(1, -1), glm::vec2(1, 1), glm::vec2(-1, 1)}) {
      const glm::vec3 p = (n + u * c.x + v * c.y) * 0.5f;
      m->positions.insert(m->positions.end(), {p.x, p.y, p.z});
      m->normals.insert(m->normals.end(), {n.x, n.y, n.z});
      m->uvs.insert(m->uvs.end(), {0.5f + 0.5f * c.x, 0.5f + 0.5f * c.y});
    }
    // u x v = n: (u, v) counter-clockwise seen from outside.
    m->indices.insert(m->indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
  }
  return m;
}

}  // namespace

std::shared_ptr<const TriangleMesh> unit_cube() {
  static const std::shared_ptr<const TriangleMesh> cube = make_cube();
  return cube;
}

}  // namespace sdfreel
