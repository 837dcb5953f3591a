#pragma once
// A unit cube centred at the origin (24 vertices: face normals and per-face uvs, counter-clockwise
// seen from outside): the box every mesh pass scales and places by its instance matrix.
#include <memory>

#include "render/triangle_mesh.h"

namespace sdfreel {

// One shared copy (backends cache their upload by this pointer).
std::shared_ptr<const TriangleMesh> unit_cube();

}  // namespace sdfreel
