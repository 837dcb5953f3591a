#include "bench_case.h"

#include <stdexcept>
#include <variant>

#include "scenes/registry.h"

namespace sdfreel::mesh_bench {

std::vector<CaseSpec> standard_cases() {
  return {
      {"hall", "museum", 2.0, true}, {"fur", "fur", 2.0, false}, {"museum", "museum", 2.0, false}};
}

BenchCase make_case(const CaseSpec& spec, int width, int height, int samples) {
  const SceneInfo* info = find_scene(spec.scene);
  if (!info) throw std::runtime_error("no scene '" + spec.scene + "'");
  BenchCase c;
  c.name = spec.name;
  c.ctx.width = width;
  c.ctx.height = height;
  c.ctx.samples = samples;
  c.ctx.scene_time = c.ctx.video_time = spec.time;
  c.ctx.quality = Quality::Final;
  c.ctx.pose = info->default_camera;
  c.ctx.params = ParamValues(&info->params);
  finish_frame_context(c.ctx);
  c.scene = info->make();
  c.scene->prepare(c.ctx);
  const FramePlan plan = c.scene->frame_plan(c.ctx);
  c.camera = make_camera_model(c.ctx.camera, width, height, plan.near_plane, plan.far_plane);
  c.targets = plan_targets(plan);
  for (const Pass& p : plan.passes) {
    const MeshPass* m = std::get_if<MeshPass>(&p);
    // Passes that ray-march inside their mesh (shade_depth) find their surface by marching, not
    // by the mesh: not what is compared here.
    if (!m || !m->shade || (spec.hall_only && m->name != "hall")) continue;
    c.passes.push_back(*m);
  }
  if (c.passes.empty()) throw std::runtime_error("case '" + spec.name + "' has no mesh pass");
  return c;
}

FlatTriangles flatten(const BenchCase& c) {
  FlatTriangles out;
  for (size_t p = 0; p < c.passes.size(); ++p) {
    const MeshPass& pass = c.passes[p];
    const TriangleMesh& m = *pass.mesh;
    out.first_of_pass.push_back(uint32_t(out.count()));
    for (size_t i = 0; i < pass.instances.size(); ++i) {
      const MeshInstance& inst = pass.instances[i];
      for (size_t t = 0; t < m.triangle_count(); ++t) {
        for (int k = 0; k < 3; ++k) {
          const unsigned v = m.index(t * 3 + size_t(k));
          const glm::vec3 position(m.positions[v * 3], m.positions[v * 3 + 1],
                                   m.positions[v * 3 + 2]);
          const glm::vec3 normal =
              m.normals.empty()
                  ? glm::vec3(0.0f)
                  : glm::vec3(m.normals[v * 3], m.normals[v * 3 + 1], m.normals[v * 3 + 2]);
          // The rasteriser's vertex stage, written the same way so the positions are the same bits.
          out.world.push_back(pass.place ? pass.place(inst, position, normal).world
                                         : glm::vec3(inst.model * glm::vec4(position, 1.0f)));
          out.uv.push_back(m.uvs.empty() ? glm::vec2(0.0f)
                                         : glm::vec2(m.uvs[v * 2], m.uvs[v * 2 + 1]));
        }
        out.pass_of.push_back(uint32_t(p));
        out.instance_of.push_back(uint32_t(i));
      }
    }
  }
  out.first_of_pass.push_back(uint32_t(out.count()));
  return out;
}

}  // namespace sdfreel::mesh_bench
