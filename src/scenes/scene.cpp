#include "scenes/scene.h"

namespace sdfreel {

FramePlan Scene::frame_plan(const FrameContext&) const {
  RayPass pass;
  pass.name = "radiance";
  pass.packet = [this](const RayPacket& rays, RayPassOutput& out, RayStats& stats) {
    radiance_packet(rays, out.colour, stats);
    for (int i = 0; i < LANES; ++i) out.keep[i] = true;
  };
  pass.scalar = [this](const Ray& ray, glm::vec3& colour, float&, bool& keep, RayStats& stats) {
    colour = radiance(ray, stats);
    keep = true;
  };
  FramePlan plan;
  plan.passes.push_back(std::move(pass));
  return plan;
}

void Scene::radiance_packet(const RayPacket& rays, glm::vec3* out, RayStats& stats) const {
  for (int i = 0; i < rays.count; ++i) {
    const LaneEvalScope lane(stats, i);
    out[i] = radiance(rays.ray(i), stats);
  }
}

std::vector<CameraPose> test_camera_poses(const SceneInfo& info) {
  std::vector<CameraPose> out{info.default_camera};
  CameraPose down = info.default_camera;
  down.target = down.position + glm::dvec3(0.3, -2.0, 1.0);
  out.push_back(down);
  CameraPose flat = info.default_camera;
  flat.target = flat.position + glm::dvec3(1.0, -0.02, 0.4);
  flat.fov_deg = 20.0;
  out.push_back(flat);
  out.insert(out.end(), info.test_poses.begin(), info.test_poses.end());
  return out;
}

}  // namespace sdfreel
