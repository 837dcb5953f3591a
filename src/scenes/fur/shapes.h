#pragma once
// The exhibit's three furry shapes: their meshes (positions, smooth normals, UVs scaled so strand
// cells are roughly square) and the support distances their collisions use: a shape turned any
// way meets the floor and the walls at depths that depend on its turn.
#include <glm/glm.hpp>
#include <memory>

#include "render/triangle_mesh.h"

namespace sdfreel::fur {

enum class Shape { Sphere, RoundedCube, Torus };

constexpr double SPHERE_RADIUS = 0.15;
constexpr double CUBE_HALF = 0.12, CUBE_ROUNDING = 0.04;
constexpr double TORUS_MAJOR = 0.13, TORUS_MINOR = 0.055;

// Unit-size meshes are never needed: each mesh is built at the sizes above, once.
std::shared_ptr<const TriangleMesh> shape_mesh(Shape s);

// Distance from the centre to the plane that touches the shape (scaled by `scale`, turned by
// `turn`, exhibit space) and faces along axis `axis` (0 x: the walls, 1 y: the floor, 2 z): the
// support function of a box, a sphere or a torus. The shapes are symmetric, so either side.
double support(Shape s, double scale, const glm::dmat3& turn, int axis);

}  // namespace sdfreel::fur
