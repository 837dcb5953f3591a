#include "scenes/museum/lattice_tower.h"

namespace sdfreel::museum {

namespace {
const glm::vec3 PAINTED_WHITE(0.82f, 0.81f, 0.78f);
constexpr float PAINT_ROUGHNESS = 0.6f;
}  // namespace

int lattice_bar_count() {
  const glm::ivec3 n = LATTICE_CELLS + 1;  // nodes along each axis
  return n.y * n.z + n.x * n.z + n.x * n.y;
}

void add_lattice_tower(std::vector<HallBox>& boxes, const glm::vec3& top) {
  const float h = 0.5f * LATTICE_BAR;
  const glm::vec3 size = glm::vec3(LATTICE_CELLS) * LATTICE_CELL + LATTICE_BAR;
  const glm::vec3 lo = top + glm::vec3(-0.5f * size.x, LATTICE_GAP, -0.5f * size.z);
  for (int axis = 0; axis < 3; ++axis) {
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    for (int i = 0; i <= LATTICE_CELLS[u]; ++i)
      for (int j = 0; j <= LATTICE_CELLS[v]; ++j) {
        glm::vec3 a = lo, b = lo + size;
        const float cu = lo[u] + h + LATTICE_CELL * float(i);
        const float cv = lo[v] + h + LATTICE_CELL * float(j);
        a[u] = cu - h, b[u] = cu + h;
        a[v] = cv - h, b[v] = cv + h;
        boxes.push_back({a, b, PAINTED_WHITE, PAINT_ROUGHNESS});
      }
  }
}

}  // namespace sdfreel::museum
