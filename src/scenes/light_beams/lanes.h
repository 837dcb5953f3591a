#pragma once
// light_beams in eight lanes: the CPU backend's packet path for the penumbra and exact estimators
// (every preset but the bench's naive, whose seed march stays scalar lane by lane). Each lane
// performs the scalar operations of render.cpp and visibility.cpp in the same order: same bits,
// same RayStats (tests/scenes/light_beams/lanes_test.cpp).
#include <glm/glm.hpp>

#include "scenes/light_beams/uniforms.h"
#include "scenes/scene.h"

namespace sdfreel::light_beams {

// out[i] == sceneRadiance(rays.ray(i), u, stats) for i < rays.count, adding the same stats.
void radiancePacket(const RayPacket& rays, const BeamsUniforms& u, glm::vec3* out, RayStats& stats);

}  // namespace sdfreel::light_beams
