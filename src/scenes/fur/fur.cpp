// Scene "fur" (seed 004, exhibit 3): three shapes with shell-textured fur in a glass case on a
// plinth, pushed by the timeline so that they jump, bounce off the floor and walls of the case and
// come to rest, their fur trailing the motion; the sphere grows and shrinks.
//
// Parameters (each fur has its own set, prefix sphere_, cube_ or torus_):
//   <fur>_length, _density, _thickness, _curvature, _base_color, _tip_color, _shells
//       shell texturing: N = shells shells, shell i at height h = i / N pushed out by h * length;
//       one strand per UV cell (density cells per UV unit) of height mix(0.35, 1, hash(cell)),
//       kept where length(local) <= thickness * (rand - h); colour from base (h = 0) to tip.
//   push_times     TIME of up to three pushes (negative: none); animate it with step keys.
//   push_strength  scale of each push's upward and sideways speed and spin.
//   grow_amount, grow_period  the sphere's size 1 + amount * sin(2 pi TIME / period).
//   displacement_strength     how far the tips follow the fur spring (fur/physics.h).
//   light_intensity           the key light.
// The exhibit itself (case, shapes, physics) is fur/exhibit.h, shared with the museum; this file
// adds a dark room and the plinth.
#include <glm/gtc/matrix_transform.hpp>
#include <memory>

#include "scenes/common/surface_output.h"
#include "scenes/fur/exhibit.h"
#include "scenes/scene.h"

namespace sdfreel {
namespace {

const glm::vec3 BACKGROUND(0.018f, 0.02f, 0.025f);
constexpr float PLINTH_TOP = 0.9f;
constexpr float CASE_FLOOR = 0.04f;   // the case's floor slab stands on the plinth
constexpr float NEAR_PLANE = 0.004f;  // depth is 32-bit float: 0.1 mm steps at 3 m

class FurScene : public Scene {
 public:
  void prepare(const FrameContext& ctx) override {
    params_ = fur::read_exhibit_params(ctx.params);
    params_.hit_mask = ctx.march.hit_mask;
    params_.surface = ctx.march.surface;
    params_.eye = ctx.camera.origin;
    pose_ = fur::exhibit_pose(params_.physics, ctx.scene_time);
  }
  glm::vec3 radiance(const Ray&, RayStats&) const override {
    if (params_.surface != SURFACE_COLOUR) return noSurface(params_.surface);
    return params_.hit_mask ? glm::vec3(0.0f) : BACKGROUND;
  }
  // Every ray of the background sees the same colour, which radiance() gives without the ray: one
  // call a packet instead of one a lane (this pass covers every pixel of every sample).
  void radiance_packet(const RayPacket& rays, glm::vec3* out, RayStats& stats) const override {
    const glm::vec3 c = radiance(rays.ray(0), stats);
    for (int i = 0; i < rays.count; ++i) out[i] = c;
  }
  std::vector<ShaderUniform> shader_uniforms() const override {
    return {{"u_hit_mask", 1, {params_.hit_mask ? 1.0f : 0.0f}},
            {"u_surface", 1, {float(params_.surface)}}};
  }
  FramePlan frame_plan(const FrameContext& ctx) const override {
    FramePlan plan = Scene::frame_plan(ctx);  // the background, one colour
    RayStats none;
    const Ray any_ray{glm::vec3(0.0f), glm::vec3(0.0f, 0.0f, 1.0f), 0.0f};
    std::get<RayPass>(plan.passes[0]).uniform_colour = radiance(any_ray, none);
    // Close enough to the fur to stand in it (the outer shell is 2.5-7 cm from the skin): the
    // default 5 cm near plane would cut the skin away and show the case through the shape.
    plan.near_plane = NEAR_PLANE;
    const glm::mat4 model =
        glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, PLINTH_TOP + CASE_FLOOR, 0.0f));
    const fur::CaseLook look = fur::exhibit_look(model, params_, pose_);
    const glm::vec3 stone(0.5f, 0.48f, 0.45f), floor(0.16f, 0.14f, 0.13f);
    plan.passes.push_back(fur::lit_boxes_pass(
        "room",
        {fur::box_instance(glm::mat4(1.0f), {0.0f, -0.05f, 0.0f}, {8.0f, 0.05f, 8.0f}, floor),
         fur::box_instance(glm::mat4(1.0f), {0.0f, PLINTH_TOP * 0.5f, 0.0f},
                           {0.95f, PLINTH_TOP * 0.5f, 0.6f}, stone)},
        look));
    fur::add_exhibit_passes(plan, model, params_, pose_);
    return plan;
  }

 private:
  fur::ExhibitParams params_;
  fur::ExhibitPose pose_;
};

// Close to the fur (strands a few pixels wide), and low along the case floor (fur edge-on).
std::vector<CameraPose> test_poses() {
  return {CameraPose{{-0.3, 1.25, -0.75}, {-0.45, 1.05, 0.0}, 35.0, 0.0},
          CameraPose{{0.9, 0.97, -1.4}, {0.0, 1.0, 0.0}, 30.0, 0.0}};
}

}  // namespace

SceneInfo fur_scene_info() {
  SceneInfo info;
  info.name = "fur";
  info.description =
      "Seed 004's exhibit 3: a sphere, a rounded cube and a torus with different shell-textured "
      "fur (N shells extruded along the normal, strands from an integer hash per UV cell, "
      "half-Lambert and fake ambient occlusion) in a case on a plinth. Pushes scheduled by the "
      "timeline (push_times) make them jump and bounce off the floor and walls of the case; the "
      "fur trails their motion on a damped spring; the sphere grows and shrinks.";
  info.params = fur::exhibit_param_specs();
  info.default_camera = CameraPose{{0.0, 1.65, -2.3}, {0.0, 1.12, 0.0}, 38.0, 0.0};
  info.test_poses = test_poses();
  info.shader = "fur/fur.glsl";
  info.draws_surfaces = true;
  info.make = [] { return std::unique_ptr<Scene>(new FurScene()); };
  return info;
}

}  // namespace sdfreel
