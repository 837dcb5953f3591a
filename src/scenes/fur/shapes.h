#pragma once
// The exhibit's three furry shapes: their meshes (positions, smooth normals, UVs scaled so strand
// cells are roughly square) and the support distances their collisions use. Shapes only turn about
// the vertical axis, so a shape meets the floor at a fixed depth below its centre and a wall at a
// depth that depends on its yaw.
#include <memory>

#include "render/triangle_mesh.h"

namespace sdfreel::fur {

enum class Shape { Sphere, RoundedCube, Torus };

constexpr double SPHERE_RADIUS = 0.15;
constexpr double CUBE_HALF = 0.12, CUBE_ROUNDING = 0.04;
constexpr double TORUS_MAJOR = 0.13, TORUS_MINOR = 0.055;

// Unit-size meshes are never needed: each mesh is built at the sizes above, once.
std::shared_ptr<const TriangleMesh> shape_mesh(Shape s);

// Distance from the centre down to the floor contact, for a shape scaled by `scale`.
double support_down(Shape s, double scale);
// Distance from the centre to a wall whose normal is the x (or z) axis, at yaw `yaw`.
double support_side(Shape s, double scale, double yaw);

}  // namespace sdfreel::fur
