#include "scenes/scene.h"

namespace sdfreel {

M8 RayPacket::valid() const {
  M8 m;
  for (int i = 0; i < LANES; ++i) m[i] = i < count ? -1 : 0;
  return m;
}

void Scene::radiance_packet(const RayPacket& rays, glm::vec3* out, RayStats& stats) const {
  for (int i = 0; i < rays.count; ++i) out[i] = radiance(rays.ray(i), stats);
}

}  // namespace sdfreel
