// Scene "lenticular_card" (seed 004, exhibit 2): a lenticular print on a stand. Its two prints
// are 16 views each of our own lantern_festival and sdf_morph scenes from slightly different
// angles (source_views.h, rendered once and cached on disk by content), interlaced into strips
// (interlace.h, the same code as `sdfreel interlace`) under a sheet of cylindrical lenslets: each
// ray refracts into the sheet and reads the strip its angle selects (optics.h), so turning the
// card or moving the camera wiggles the picture, with repeat zones where the views flip. The
// sheet's ridged gloss is a noise normal map stretched along the lenses, and the card scrolls
// between its two prints like a billboard (the seed's offset function of time).
//
// Parameters (`sdfreel scenes lenticular_card`):
//   card_yaw        turns the card on its stand (degrees about +y): animate it to see the views
//   ior             the sheet's index of refraction
//   thickness       the sheet's thickness over the lens pitch (~ the lenses' focal length)
//   gloss           scale of the sheet's reflections (0: a bare print)
//   ridge_noise     strength of the noise normal map on the lens ridges
//   scroll_period   seconds from one print to the next (hold, then slide)
//   scroll_hold     share of the period the print holds still before it slides
// The card and stand are one ray pass (exhibit.h) that the museum hall reuses on its plinth; here
// it and the backdrop are one pass.
#include <glm/gtc/matrix_transform.hpp>
#include <memory>

#include "scenes/common/uniform_list.h"
#include "scenes/lenticular_card/backdrop.h"
#include "scenes/lenticular_card/exhibit.h"
#include "scenes/scene.h"

namespace sdfreel {
namespace {

using namespace lenticular_card;

class LenticularCardScene : public Scene {
 public:
  void prepare(const FrameContext& ctx) override {
    prints_ = &default_card_prints();
    const ParamValues& p = ctx.params;
    look_.ior = float(p.scalar("ior"));
    look_.thickness = float(p.scalar("thickness"));
    look_.gloss = float(p.scalar("gloss"));
    look_.ridge_noise = float(p.scalar("ridge_noise"));
    look_.scroll_period = p.scalar("scroll_period");
    look_.scroll_hold = p.scalar("scroll_hold");
    light_ = glm::normalize(look_.light_world);
    const double yaw = glm::radians(p.scalar("card_yaw"));
    model_ = glm::mat4(glm::rotate(glm::dmat4(1.0), yaw, glm::dvec3(0.0, 1.0, 0.0)));
    card_ = card_uniforms(model_, *prints_, look_, ctx.scene_time);
    card_.hit_mask = ctx.march.hit_mask;
    card_.surface = ctx.march.surface;
  }
  glm::vec3 radiance(const Ray& ray, RayStats&) const override {
    // The plan's two passes in one: the card (nearer than anything of the backdrop) over it.
    glm::vec3 colour;
    float t;
    if (shadeCard(ray, card_, CardTextures{prints_->print.get(), prints_->ridges.get()}, colour, t))
      return colour;
    return backdrop(ray, light_, card_.hit_mask, card_.surface);
  }
  // One ray pass, the card over the backdrop: where the card's own pass would pass its depth
  // test (LESS against the cleared depth, 1) its colour, elsewhere the backdrop's. The same
  // pixels as the backdrop pass followed by the card's, with no depth target, so the CPU traces
  // every sample of a pixel in one packet (cpu_ray_pass_resolved.h); GL runs the same in
  // lenticular_card.glsl.
  FramePlan frame_plan(const FrameContext& ctx) const override {
    FramePlan plan;
    const RayPass card = card_ray_pass(plan, model_, *prints_, look_, ctx);
    const glm::vec3 light = light_;
    const bool mask = card_.hit_mask;
    const int surface = card_.surface;
    RayPass scene;
    scene.name = "lenticular card over its backdrop";
    scene.uniforms = card.uniforms;
    scene.scalar = [card = card.scalar, light, mask, surface](const Ray& ray, glm::vec3& colour,
                                                              float&, bool& keep, RayStats& stats) {
      float depth = 1.0f;
      bool hit = false;
      card(ray, colour, depth, hit, stats);
      if (!(hit && depth < 1.0f)) colour = backdrop(ray, light, mask, surface);
      keep = true;
    };
    scene.packet = [card = card.packet, light, mask, surface](const RayPacket& rays,
                                                              RayPassOutput& out, RayStats& stats) {
      card(rays, out, stats);
      bool backdrop_seen = false;
      for (int i = 0; i < rays.count; ++i) {
        out.keep[i] = out.keep[i] && out.depth[i] < 1.0f;  // now: the card is seen
        backdrop_seen |= !out.keep[i];
      }
      if (backdrop_seen) {
        const V3x8 back = backdrop(rays, light, mask, surface);
        for (int i = 0; i < rays.count; ++i)
          if (!out.keep[i]) out.colour[i] = back.lane(i);
      }
      for (int i = 0; i < rays.count; ++i) out.keep[i] = true;
    };
    plan.passes.push_back(std::move(scene));
    return plan;
  }
  std::vector<ShaderUniform> shader_uniforms() const override {
    return UniformList()
        .v3("u_backdrop_light", light_)
        .flag("u_backdrop_hit_mask", card_.hit_mask)
        .f("u_backdrop_surface", float(card_.surface))
        .uniforms();
  }
  std::vector<ShaderTexture> shader_textures() const override {
    return card_shader_textures(*prints_);
  }
  uint64_t shader_textures_key() const override { return prints_ ? prints_->key : 0; }

 private:
  const CardPrints* prints_ = nullptr;
  CardLook look_;
  glm::vec3 light_{0.0f, 1.0f, 0.0f};
  glm::mat4 model_{1.0f};
  CardUniforms card_;
};

ParamSpec scalar(const char* name, double def, double min, double max, const char* doc) {
  return ParamSpec{name, 1, {def}, min, max, doc};
}

// Nearly edge-on (grazing rays on the lenses and the card's edge), and from behind.
std::vector<CameraPose> test_poses() {
  return {CameraPose{{1.5, 0.32, 0.06}, {0.0, 0.3, 0.0}, 30.0, 0.0},
          CameraPose{{0.4, 0.5, -1.4}, {0.0, 0.3, 0.0}, 35.0, 0.0}};
}

}  // namespace

SceneInfo lenticular_card_scene_info() {
  SceneInfo info;
  info.name = "lenticular_card";
  info.description =
      "A lenticular card on a stand (seed 004, exhibit 2): two prints, each 16 views of our own "
      "lantern_festival and sdf_morph scenes rendered from slightly different angles (cached on "
      "disk by content), interlaced into strips under a sheet of cylindrical lenslets. Each ray "
      "refracts into the sheet and reads the strip its angle selects, so turning the card "
      "(card_yaw) or moving the camera wiggles the picture, with repeat zones where the views "
      "flip; a noise normal map stretched along the lenses gives the ridged gloss, and the card "
      "scrolls between its two prints like a billboard.";
  info.params = {
      scalar("card_yaw", 0.0, -180.0, 180.0, "turns the card on its stand, degrees about +y"),
      scalar("ior", 1.56, 1.0, 3.0, "the lens sheet's index of refraction"),
      scalar("thickness", 1.5, 0.1, 10.0, "sheet thickness over lens pitch (~ focal length)"),
      scalar("gloss", 1.0, 0.0, 4.0, "scale of the sheet's reflections (0: a bare print)"),
      scalar("ridge_noise", 0.1, 0.0, 2.0, "strength of the noise normal map on the ridges"),
      scalar("scroll_period", 6.0, 0.1, 1e6, "seconds from one print to the next"),
      scalar("scroll_hold", 0.7, 0.0, 0.95, "share of the period a print holds still"),
  };
  info.default_camera = CameraPose{{0.0, 0.42, 1.45}, {0.0, 0.3, 0.0}, 32.0, 0.0};
  info.test_poses = test_poses();
  info.shader = "lenticular_card/lenticular_card.glsl";
  info.draws_surfaces = true;
  info.make = [] { return std::unique_ptr<Scene>(new LenticularCardScene()); };
  return info;
}

}  // namespace sdfreel
