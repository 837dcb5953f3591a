#pragma once
// The exhibit case and the room around it: boxes lit by the key light, with soft contact shadows
// under the furry shapes. C++ twin of shaders/fur/case.glsl.
#include <array>
#include <glm/glm.hpp>
#include <memory>

#include "render/frame_plan.h"
#include "scenes/fur/physics.h"

namespace sdfreel::fur {

struct CaseLook {
  glm::vec3 light_dir{0.0f, 1.0f, 0.0f}, light{1.0f}, ambient{0.0f};
  std::array<glm::vec4, BODY_COUNT> bodies{};  // world centre, footprint radius
  bool hit_mask = false;                       // draw hit id 0 instead
  int surface = 0;  // MarchSettings::surface: draw the distance from `eye` or the normal
  glm::vec3 eye{0.0f};
};

// A box from -1 to 1 on each axis with flat faces (24 vertices), for instancing.
std::shared_ptr<const TriangleMesh> box_mesh();
// Instance model of the box with this centre and half size inside `model`; data = colour.
MeshInstance box_instance(const glm::mat4& model, const glm::vec3& centre, const glm::vec3& half,
                          const glm::vec3& colour);
glm::vec4 shade_case(const CaseLook& look, const MeshFragment& f);

}  // namespace sdfreel::fur
