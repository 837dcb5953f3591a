#include "scenes/museum/fur_exhibit.h"

#include <glm/gtc/matrix_transform.hpp>
#include <variant>

#include "scenes/fur/exhibit.h"
#include "scenes/fur/exhibit_params.h"

namespace sdfreel::museum {
namespace {

// The case is 1.64 m wide outside (fur/physics.h): this fits it on the 0.7 m plinth top.
constexpr float CASE_SCALE = 0.42f;
// The case opens towards its -z; the plinth stands on the hall's -z side, so turn it half round.
constexpr float CASE_YAW = 3.14159265f;

}  // namespace

// Turned, scaled and standing on the plinth top with its floor slab (not sunk into it: the slab's
// top face and the plinth's would be one plane, drawn by each rasteriser its own way).
glm::mat4 fur_case_pose() {
  const glm::mat4 turned = glm::rotate(glm::mat4(1.0f), CASE_YAW, glm::vec3(0, 1, 0));
  const glm::mat4 scaled = glm::scale(turned, glm::vec3(CASE_SCALE));
  return glm::translate(scaled, glm::vec3(0.0f, fur::CASE_FLOOR_THICKNESS, 0.0f));
}

ExhibitPasses fur_exhibit() {
  return [](FramePlan& plan, const glm::mat4& top, const ExhibitStage& stage) {
    fur::ExhibitParams p = fur::read_exhibit_params(stage.frame.params, FUR_PARAM_PREFIX);
    p.hit_mask = stage.frame.march.hit_mask;
    p.hit_id_base = FUR_HIT_ID_BASE;
    p.surface = stage.frame.march.surface;
    p.eye = stage.frame.camera.origin;
    const size_t first = plan.passes.size();
    fur::add_exhibit_passes(plan, top * fur_case_pose(), p, stage.frame.scene_time);
    // The fur's passes draw into the hall's targets, not the frame's.
    for (size_t i = first; i < plan.passes.size(); ++i) {
      MeshPass& pass = std::get<MeshPass>(plan.passes[i]);
      pass.colour = stage.colour;
      pass.depth = stage.depth;
    }
  };
}

}  // namespace sdfreel::museum
