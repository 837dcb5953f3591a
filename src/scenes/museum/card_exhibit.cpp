#include "scenes/museum/card_exhibit.h"

#include <glm/gtc/matrix_transform.hpp>
#include <variant>

#include "scenes/lenticular_card/exhibit.h"

namespace sdfreel::museum {
namespace {

// Facing (sin yaw, 0, cos yaw) = (0.57, 0, -0.82): across the hall (-z) and towards its door end
// (+x), where the walkthrough comes from.
constexpr float CARD_YAW = 2.53f;
// The card's key light in the world. The sun comes from behind this plinth (the window is west,
// the sun south-west), so the card is lit as by the hall's bright side instead: from above and
// in front of its face.
const glm::vec3 CARD_KEY_LIGHT(0.35f, 0.8f, -0.5f);

}  // namespace

glm::mat4 card_pose() {
  return glm::rotate(glm::mat4(1.0f), CARD_YAW, glm::vec3(0, 1, 0));
}

ExhibitPasses card_exhibit(const lenticular_card::CardPrints& prints) {
  return [&prints](FramePlan& plan, const glm::mat4& top, const ExhibitStage& stage) {
    lenticular_card::CardLook look;
    look.light_world = CARD_KEY_LIGHT;
    look.hit_id_base = CARD_HIT_ID_BASE;
    const size_t first = plan.passes.size();
    lenticular_card::add_exhibit_passes(plan, top * card_pose(), prints, look, stage.frame);
    // The card's passes draw into the hall's targets, not the frame's.
    for (size_t i = first; i < plan.passes.size(); ++i) {
      RayPass& pass = std::get<RayPass>(plan.passes[i]);
      pass.colour = stage.colour;
      pass.depth = stage.depth;
    }
  };
}

}  // namespace sdfreel::museum
