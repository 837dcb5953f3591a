#pragma once
// The museum's only mesh: a unit cube centred at the origin (24 vertices with face normals,
// counter-clockwise outside), instanced for every box of the hall and for exhibit 1's bound.
#include <glm/glm.hpp>
#include <memory>

#include "render/frame_plan.h"
#include "render/triangle_mesh.h"

namespace sdfreel::museum {

std::shared_ptr<const TriangleMesh> unit_cube();

// The instance of the unit cube that fills [lo, hi], with `data`.
MeshInstance box_instance(const glm::vec3& lo, const glm::vec3& hi, const glm::vec4& data);

}  // namespace sdfreel::museum
