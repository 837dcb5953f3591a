#include "scenes/lenticular_card/exhibit.h"

#include "render/camera_model.h"
#include "render/quality.h"
#include "scenes/common/uniform_list.h"
#include "scenes/lenticular_card/card_lanes.h"
#include "scenes/lenticular_card/optics.h"

namespace sdfreel::lenticular_card {
namespace {

glm::mat4 inverse_in_double(const glm::mat4& m) {
  return glm::mat4(glm::inverse(glm::dmat4(m)));
}

// The window depth of a hit at t along a unit primary ray (camera_model.h's convention).
float hit_depth(const CameraModel& cam, const glm::vec3& forward, const glm::vec3& dir, float t) {
  return window_depth(cam, t * (dir.x * forward.x + dir.y * forward.y + dir.z * forward.z));
}

}  // namespace

CardUniforms card_uniforms(const glm::mat4& model, const CardPrints& prints, const CardLook& look,
                           double time) {
  CardUniforms u;
  u.world_to_local = inverse_in_double(model);
  const glm::dvec3 light = glm::dmat3(glm::dmat4(u.world_to_local)) * glm::dvec3(look.light_world);
  u.light = glm::vec3(glm::normalize(light));
  u.scroll = float(scroll_offset(time, look.scroll_period, look.scroll_hold));
  u.ior = look.ior;
  u.thickness = look.thickness;
  u.gloss = look.gloss;
  u.ridge_noise = look.ridge_noise;
  u.lenses = prints.lenses;
  u.views = prints.views;
  u.view_height = prints.view_height;
  u.hit_id_base = look.hit_id_base;
  return u;
}

std::vector<ShaderUniform> card_shader_uniforms(const CardUniforms& u) {
  UniformList list("u_card");
  std::vector<float> m;
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) m.push_back(u.world_to_local[c][r]);
  list.add("world_to_local", 16, m)
      .v3("light", u.light)
      .f("scroll", u.scroll)
      .f("ior", u.ior)
      .f("thickness", u.thickness)
      .f("gloss", u.gloss)
      .f("ridge_noise", u.ridge_noise)
      .f("lenses", float(u.lenses))
      .f("views", float(u.views))
      .f("view_height", float(u.view_height))
      .flag("hit_mask", u.hit_mask)
      .f("surface", float(u.surface))
      .f("hit_id_base", u.hit_id_base);
  return list.uniforms();
}

RayPass card_ray_pass(const FramePlan& plan, const glm::mat4& model, const CardPrints& prints,
                      const CardLook& look, const FrameContext& ctx) {
  CardUniforms u = card_uniforms(model, prints, look, ctx.scene_time);
  u.hit_mask = ctx.march.hit_mask;
  u.surface = ctx.march.surface;
  const CameraModel cam =
      make_camera_model(ctx.camera, ctx.width, ctx.height, plan.near_plane, plan.far_plane);
  const glm::vec3 forward = ctx.camera.forward;
  // The lambdas own what they read: the textures outlive the plan's scene.
  const std::shared_ptr<const StripPrint> print = prints.print;
  const std::shared_ptr<const Texture> ridges = prints.ridges;
  auto shade = [u, cam, forward, print, ridges](const Ray& ray, glm::vec3& colour, float& depth,
                                                bool& keep) {
    float t = 0.0f;
    keep = shadeCard(ray, u, CardTextures{print.get(), ridges.get()}, colour, t);
    if (keep) depth = hit_depth(cam, forward, ray.dir, t);
  };
  RayPass pass;
  pass.name = "lenticular card";
  pass.depth = DEPTH_TARGET;
  pass.depth_test = DepthTest::TestAndWrite;
  pass.shader = "lenticular_card/card_pass.glsl";
  pass.uniforms = card_shader_uniforms(u);
  pass.scalar = [shade](const Ray& ray, glm::vec3& colour, float& depth, bool& keep, RayStats&) {
    shade(ray, colour, depth, keep);
  };
  pass.packet = [shade, u, cam, forward, print, ridges](const RayPacket& rays, RayPassOutput& out,
                                                        RayStats&) {
    const M8 maybe = may_hit_card(rays, u);
    if (u.hit_mask || u.surface != SURFACE_COLOUR) {  // ids and surfaces: one ray at a time
      for (int i = 0; i < rays.count; ++i)
        if (lane(maybe, i))
          shade(rays.ray(i), out.colour[i], out.depth[i], out.keep[i]);
        else
          out.keep[i] = false;  // what shadeCard says of a miss
      return;
    }
    M8 hit = maybe;
    V3x8 colour;
    F8 t;
    if (any(maybe))
      hit &= shadeCard_lanes(rays, u, CardTextures{print.get(), ridges.get()}, colour, t);
    for (int i = 0; i < rays.count; ++i) {
      out.keep[i] = lane(hit, i);
      if (!out.keep[i]) continue;
      out.colour[i] = colour.lane(i);
      out.depth[i] = hit_depth(cam, forward, rays.dir.lane(i), t[i]);
    }
  };
  return pass;
}

void add_exhibit_passes(FramePlan& plan, const glm::mat4& model, const CardPrints& prints,
                        const CardLook& look, const FrameContext& ctx) {
  plan.passes.push_back(card_ray_pass(plan, model, prints, look, ctx));
}

}  // namespace sdfreel::lenticular_card
