#pragma once
// The museum's only mesh is the shared unit cube (render/unit_cube.h), instanced for every box of
// the hall and for exhibit 1's bound.
#include <glm/glm.hpp>
#include <memory>

#include "render/frame_plan.h"
#include "render/unit_cube.h"

namespace sdfreel::museum {

using sdfreel::unit_cube;

// The instance of the unit cube that fills [lo, hi], with `data`.
MeshInstance box_instance(const glm::vec3& lo, const glm::vec3& hi, const glm::vec4& data);

}  // namespace sdfreel::museum
