#include "scenes/fur/exhibit.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <string>
#include <utility>

#include "scenes/fur/shading_lanes.h"
#include "scenes/fur/shell_shading.h"
#include "scenes/fur/turning.h"
#include "sdf/det_math.h"

namespace sdfreel::fur {
namespace {

constexpr double MAX_LAG = 0.5;             // |D| is clamped here (metres) before the strength
constexpr double MAX_TWIST = 0.5235987756;  // 30 degrees, as the seed's driver clamps
const glm::vec3 CASE_COLOUR(0.42f, 0.4f, 0.37f), BACK_COLOUR(0.3f, 0.33f, 0.36f);

ShaderUniform vec3_uniform(const char* name, const glm::vec3& v) {
  return {name, 3, {v.x, v.y, v.z}};
}

std::vector<ShaderUniform> light_uniforms(const CaseLook& l) {
  return {vec3_uniform("u_light_dir", l.light_dir), vec3_uniform("u_light", l.light),
          vec3_uniform("u_ambient", l.ambient)};
}

std::vector<MeshInstance> case_boxes(const glm::mat4& model) {
  const float h = float(CASE_HEIGHT) * 0.5f + 0.01f;
  const float x = float(CASE_HALF_X), z = float(CASE_HALF_Z);
  const float floor_half = 0.5f * CASE_FLOOR_THICKNESS;
  return {box_instance(model, {0.0f, -floor_half, 0.0f}, {x + 0.04f, floor_half, z + 0.04f},
                       CASE_COLOUR),
          box_instance(model, {0.0f, h, z + 0.02f}, {x + 0.04f, h, 0.02f}, BACK_COLOUR),
          box_instance(model, {-x - 0.02f, h, 0.0f}, {0.02f, h, z}, CASE_COLOUR),
          box_instance(model, {x + 0.02f, h, 0.0f}, {0.02f, h, z}, CASE_COLOUR)};
}

MeshPass shell_pass(const glm::mat4& model, const BodyPose& body, const FurLook& fur,
                    const ExhibitParams& p, const CaseLook& light) {
  const glm::mat3 to_world(model);
  const float world_scale = glm::length(to_world[0]);
  MeshPass pass;
  pass.name = std::string("fur shells ") + FUR_PREFIXES[int(body.shape)];
  pass.mesh = shape_mesh(body.shape);
  const glm::mat4 body_model =
      glm::scale(glm::translate(model, glm::vec3(body.position)) * glm::mat4(glm::mat3(body.turn)),
                 glm::vec3(float(body.scale)));
  const int n = std::max(1, int(std::lround(fur.shells)));
  pass.instances.clear();
  for (int i = 0; i < n; ++i)
    pass.instances.push_back({body_model, shell_data(i, n, float(fur.curvature))});
  ShellMotion m;
  m.length = float(fur.length) * world_scale;
  m.centre = glm::vec3(model * glm::vec4(glm::vec3(body.position), 1.0f));
  glm::dvec3 twist = body.fur_twist;
  if (glm::length(twist) > MAX_TWIST) twist *= MAX_TWIST / glm::length(twist);
  m.twist = to_world * glm::mat3(rotation(twist)) * glm::inverse(to_world);
  glm::dvec3 lag = body.fur_lag;
  if (glm::length(lag) > MAX_LAG) lag *= MAX_LAG / glm::length(lag);
  m.offset = to_world * glm::vec3(lag * p.displacement_strength);
  ShellLook look;
  look.density = float(fur.density);
  look.thickness = float(fur.thickness);
  look.base = glm::vec3(fur.base_color);
  look.tip = glm::vec3(fur.tip_color);
  look.light_dir = light.light_dir, look.light = light.light, look.ambient = light.ambient;
  if (p.hit_mask) look.hit_id = p.hit_id_base + float(int(body.shape) + 1);
  look.surface = p.surface;
  look.eye = p.eye;
  pass.vertex = "fur/shell.vert";
  pass.fragment = "fur/shell.glsl";
  pass.alpha_cutoff = 0.5f;
  const glm::mat4 twist4(m.twist);
  std::vector<float> twist_values(&twist4[0][0], &twist4[0][0] + 16);
  pass.uniforms = light_uniforms(light);
  pass.uniforms.push_back({"u_fur_length", 1, {m.length}});
  pass.uniforms.push_back(vec3_uniform("u_fur_centre", m.centre));
  pass.uniforms.push_back({"u_fur_twist", 16, twist_values});
  pass.uniforms.push_back(vec3_uniform("u_fur_offset", m.offset));
  pass.uniforms.push_back({"u_fur_density", 1, {look.density}});
  pass.uniforms.push_back({"u_hit_id", 1, {look.hit_id}});
  pass.uniforms.push_back({"u_surface", 1, {float(look.surface)}});
  pass.uniforms.push_back({"u_fur_thickness", 1, {look.thickness}});
  pass.uniforms.push_back(vec3_uniform("u_fur_base", look.base));
  pass.uniforms.push_back(vec3_uniform("u_fur_tip", look.tip));
  pass.place = [m](const MeshInstance& inst, const glm::vec3& pos, const glm::vec3& nrm) {
    return place_shell_vertex(m, inst, pos, nrm);
  };
  pass.shade = [look](const MeshFragment& f) { return shade_shell(look, f); };
  pass.shade8 = [look](const MeshFragments8& f, FragmentColours8& c) { shade_shell8(look, f, c); };
  return pass;
}

}  // namespace

MeshPass lit_boxes_pass(const std::string& name, std::vector<MeshInstance> boxes,
                        const CaseLook& look) {
  MeshPass pass;
  pass.name = name;
  pass.mesh = box_mesh();
  pass.instances = std::move(boxes);
  pass.fragment = "fur/case.glsl";
  pass.uniforms = light_uniforms(look);
  std::vector<float> bodies;
  for (const glm::vec4& b : look.bodies) bodies.insert(bodies.end(), {b.x, b.y, b.z, b.w});
  pass.uniforms.push_back({"u_bodies", 4, bodies});
  pass.uniforms.push_back({"u_hit_mask", 1, {look.hit_mask ? 1.0f : 0.0f}});
  pass.uniforms.push_back({"u_surface", 1, {float(look.surface)}});
  pass.shade = [look](const MeshFragment& f) { return shade_case(look, f); };
  pass.shade8 = [look](const MeshFragments8& f, FragmentColours8& c) { shade_case8(look, f, c); };
  return pass;
}

CaseLook exhibit_light(const ExhibitParams& p) {
  CaseLook l;
  l.light_dir = glm::normalize(glm::vec3(-0.35f, 0.85f, -0.45f));
  l.light = glm::vec3(1.0f, 0.95f, 0.88f) * float(p.light_intensity);
  l.ambient = glm::vec3(0.16f, 0.17f, 0.2f);
  return l;
}

CaseLook exhibit_look(const glm::mat4& model, const ExhibitParams& p, const ExhibitPose& pose) {
  CaseLook look = exhibit_light(p);
  look.hit_mask = p.hit_mask;
  look.surface = p.surface;
  look.eye = p.eye;
  const float world_scale = glm::length(glm::vec3(model[0]));
  for (int i = 0; i < BODY_COUNT; ++i) {
    const BodyPose& b = pose[size_t(i)];
    const glm::vec3 c(model * glm::vec4(glm::vec3(b.position), 1.0f));
    const float r =
        float(support(b.shape, b.scale, glm::dmat3(1.0), 0) + p.looks[size_t(i)].length * 0.5);
    look.bodies[size_t(i)] = glm::vec4(c, r * world_scale);
  }
  return look;
}

void add_exhibit_passes(FramePlan& plan, const glm::mat4& model, const ExhibitParams& p,
                        const ExhibitPose& pose) {
  const CaseLook look = exhibit_look(model, p, pose);
  plan.passes.push_back(lit_boxes_pass("fur case", case_boxes(model), look));
  for (int i = 0; i < BODY_COUNT; ++i)
    plan.passes.push_back(shell_pass(model, pose[size_t(i)], p.looks[size_t(i)], p, look));
}

void add_exhibit_passes(FramePlan& plan, const glm::mat4& model, const ExhibitParams& p, double t) {
  add_exhibit_passes(plan, model, p, exhibit_pose(p.physics, t));
}

}  // namespace sdfreel::fur
