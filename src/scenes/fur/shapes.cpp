#include "scenes/fur/shapes.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/glm.hpp>

#include "sdf/det_math.h"

namespace sdfreel::fur {
namespace {

constexpr double PI = 3.14159265358979323846;

// libm-free (sdf/det_math.h), so every machine builds the same meshes.
double dsin(double x) {
  return double(dm::sin(float(x)));
}
double dcos(double x) {
  return double(dm::cos(float(x)));
}

void add_vertex(TriangleMesh& m, const glm::dvec3& p, const glm::dvec3& n, double u, double v) {
  m.positions.insert(m.positions.end(), {float(p.x), float(p.y), float(p.z)});
  m.normals.insert(m.normals.end(), {float(n.x), float(n.y), float(n.z)});
  m.uvs.insert(m.uvs.end(), {float(u), float(v)});
}

// A (cols + 1) x (rows + 1) vertex grid starting at vertex `base`, two counter-clockwise
// triangles per quad as seen from outside when (i, j) runs along (u, v) with u x v outward.
void add_grid(TriangleMesh& m, unsigned base, int cols, int rows) {
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < cols; ++i) {
      const unsigned a = base + unsigned(j * (cols + 1) + i), b = a + 1;
      const unsigned c = a + unsigned(cols + 1), d = c + 1;
      m.indices.insert(m.indices.end(), {a, b, d, a, d, c});
    }
}

// Latitude-longitude sphere; u goes twice round so cells are square at the equator.
TriangleMesh sphere() {
  TriangleMesh m;
  const int cols = 64, rows = 32;
  for (int j = 0; j <= rows; ++j)
    for (int i = 0; i <= cols; ++i) {
      const double th = PI * j / rows, ph = 2.0 * PI * i / cols;
      const glm::dvec3 n(dsin(th) * dcos(ph), -dcos(th), -dsin(th) * dsin(ph));
      add_vertex(m, n * SPHERE_RADIUS, n, 2.0 * i / cols, double(j) / rows);
    }
  add_grid(m, 0, cols, rows);
  return m;
}

// A rounded cube: each face a grid on the unit cube, pushed to the rounded surface along the
// direction from the inner box, which also gives smooth normals across edges.
TriangleMesh rounded_cube() {
  TriangleMesh m;
  const int n = 16;
  const double inner = CUBE_HALF - CUBE_ROUNDING;
  for (int face = 0; face < 6; ++face) {
    const int axis = face / 2;
    const double sign = face % 2 ? -1.0 : 1.0;
    glm::dvec3 normal(0.0), du(0.0), dv(0.0);
    normal[axis] = sign;
    du[(axis + 1) % 3] = 1.0;
    dv[(axis + 2) % 3] = 1.0;
    if (sign < 0.0) std::swap(du, dv);  // keep du x dv pointing out
    const unsigned base = unsigned(m.vertex_count());
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) {
        const double a = 2.0 * i / n - 1.0, b = 2.0 * j / n - 1.0;
        const glm::dvec3 c = (normal + du * a + dv * b) * CUBE_HALF;
        const glm::dvec3 core = glm::clamp(c, -inner, inner);
        const glm::dvec3 dir = glm::normalize(c - core);
        add_vertex(m, core + dir * CUBE_ROUNDING, dir, face + double(i) / n, double(j) / n);
      }
    add_grid(m, base, n, n);
  }
  return m;
}

// A torus lying flat (axis +y); u goes three times round the ring.
TriangleMesh torus() {
  TriangleMesh m;
  const int cols = 72, rows = 24;
  for (int j = 0; j <= rows; ++j)
    for (int i = 0; i <= cols; ++i) {
      const double ph = 2.0 * PI * i / cols, th = 2.0 * PI * j / rows;
      const glm::dvec3 radial(dcos(ph), 0.0, -dsin(ph));
      const glm::dvec3 n = radial * dcos(th) + glm::dvec3(0.0, dsin(th), 0.0);
      add_vertex(m, radial * TORUS_MAJOR + n * TORUS_MINOR, n, 3.0 * i / cols, double(j) / rows);
    }
  add_grid(m, 0, cols, rows);
  return m;
}

}  // namespace

std::shared_ptr<const TriangleMesh> shape_mesh(Shape s) {
  static const auto meshes = [] {
    return std::array<std::shared_ptr<const TriangleMesh>, 3>{
        std::make_shared<const TriangleMesh>(sphere()),
        std::make_shared<const TriangleMesh>(rounded_cube()),
        std::make_shared<const TriangleMesh>(torus())};
  }();
  return meshes[size_t(s)];
}

double support(Shape s, double scale, const glm::dmat3& turn, int axis) {
  // The local axes' components along the world axis: turn's rows.
  const glm::dvec3 d(turn[0][axis], turn[1][axis], turn[2][axis]);
  switch (s) {
    case Shape::Sphere:
      return SPHERE_RADIUS * scale;
    case Shape::RoundedCube: {
      const double inner = CUBE_HALF - CUBE_ROUNDING;
      return scale * (inner * (std::fabs(d.x) + std::fabs(d.y) + std::fabs(d.z)) + CUBE_ROUNDING);
    }
    case Shape::Torus:  // the ring in the local x-z plane, its axis local y
      return scale * (TORUS_MAJOR * std::sqrt(std::max(0.0, 1.0 - d.y * d.y)) + TORUS_MINOR);
  }
  return 0.0;
}

}  // namespace sdfreel::fur
