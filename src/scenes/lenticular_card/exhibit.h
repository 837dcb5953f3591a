#pragma once
// The lenticular card as an exhibit any scene can place: add_exhibit_passes() appends the ray
// pass that draws the card and its stand (depth tested against what the plan drew before, and
// writing depth), given the exhibit's model matrix. The standalone scene lenticular_card uses it
// over its backdrop; the museum hall puts it on plinth 2. The host scene must also hand
// card_shader_textures(prints) to the GL backend (Scene::shader_textures), since every pass reads
// the scene's textures.
#include <glm/glm.hpp>

#include "render/frame_context.h"
#include "render/frame_plan.h"
#include "scenes/lenticular_card/card.h"
#include "scenes/lenticular_card/textures.h"

namespace sdfreel::lenticular_card {

// How the card looks and moves; the scene parameters of lenticular_card.
struct CardLook {
  glm::vec3 light_world = glm::vec3(-0.45f, 0.75f, 0.5f);  // toward the key light
  float ior = 1.56f, thickness = 1.5f, gloss = 1.0f, ridge_noise = 0.1f;
  double scroll_period = 6.0, scroll_hold = 0.7;  // seconds; share of the period held still
  float hit_id_base = 0.0f;  // MarchSettings::hit_mask: the card's and stand's ids start above
};

// The card pass's constants at `time` (TIME, seconds) for an exhibit placed by `model`.
CardUniforms card_uniforms(const glm::mat4& model, const CardPrints& prints, const CardLook& look,
                           double time);

// The GLSL uniforms of those constants (u_card_*).
std::vector<ShaderUniform> card_shader_uniforms(const CardUniforms& u);

// The card's ray pass ("lenticular card", shaders/lenticular_card/card_pass.glsl): discarded where
// a ray misses, else the colour and the hit's window depth, depth tested and written. Make it
// after the plan's near and far planes are set: the depth uses them.
RayPass card_ray_pass(const FramePlan& plan, const glm::mat4& model, const CardPrints& prints,
                      const CardLook& look, const FrameContext& ctx);

// Appends the card's ray pass ("lenticular card", shaders/lenticular_card/card_pass.glsl) to
// `plan`. Call after the plan's near and far planes are set: the depth it writes uses them.
void add_exhibit_passes(FramePlan& plan, const glm::mat4& model, const CardPrints& prints,
                        const CardLook& look, const FrameContext& ctx);

}  // namespace sdfreel::lenticular_card
