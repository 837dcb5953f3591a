#include "scenes/museum/exhibits.h"

#include <glm/gtc/matrix_transform.hpp>

#include "scenes/museum/sdf_exhibit.h"
#include "scenes/sdf_morph/geometry.h"
#include "scenes/sdf_morph/uniforms.h"

namespace sdfreel::museum {

glm::mat4 plinth_top(int plinth) {
  return glm::translate(glm::mat4(1.0f), plinth_base(plinth) + glm::vec3(0.0f, PLINTH_H, 0.0f));
}

glm::mat4 exhibit_one_model(const FrameContext& ctx) {
  const ParamValues& pv = ctx.params;
  const glm::vec3 shift(float(pv.scalar("exhibit_shift_x")), float(pv.scalar("exhibit_lift")),
                        float(pv.scalar("exhibit_shift_z")));
  const glm::mat4 m = glm::translate(plinth_top(0), shift);
  const glm::mat4 r = glm::rotate(m, float(pv.scalar("exhibit_yaw")), glm::vec3(0, 1, 0));
  return glm::scale(r, glm::vec3(float(pv.scalar("exhibit_scale"))));
}

glm::vec3 exhibit_one_centre(const FrameContext& ctx) {
  const float y = sdf_morph::OBJECT_BOUND_Y - sdf_morph::PEDESTAL_HEIGHT;
  return glm::vec3(exhibit_one_model(ctx) * glm::vec4(0.0f, y, 0.0f, 1.0f));
}

void add_exhibit_passes(FramePlan& plan, const ExhibitStage& stage,
                        const ExhibitPasses extra[PLINTH_COUNT]) {
  const sdf_morph::MorphUniforms morph = sdf_morph::make_morph_uniforms(stage.frame);
  plan.setup_passes.push_back(sdf_exhibit_shadow_pass(exhibit_one_model(stage.frame), morph));
  plan.passes.push_back(sdf_exhibit_pass(exhibit_one_model(stage.frame), morph, stage.light,
                                         *stage.probe, stage.frame, stage.camera, stage.colour,
                                         stage.depth));
  for (int i = 0; i < PLINTH_COUNT; ++i)
    if (extra && extra[i]) extra[i](plan, plinth_top(i), stage);
}

}  // namespace sdfreel::museum
