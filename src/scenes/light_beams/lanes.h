#pragma once
// light_beams in eight lanes: the CPU backend's packet path for every estimator (the seed's
// march, penumbra, exact); the hit-mask debug output stays scalar lane by lane. Each lane
// performs the scalar operations of render.cpp and visibility.cpp in the same order: same bits,
// same RayStats (tests/scenes/packet_path_test.cpp).
#include <glm/glm.hpp>
#include <vector>

#include "scenes/light_beams/uniforms.h"
#include "scenes/scene.h"

namespace sdfreel::light_beams {

// out[i] == sceneRadiance(rays.ray(i), u, stats) for i < rays.count, adding the same stats.
void radiancePacket(const RayPacket& rays, const BeamsUniforms& u, glm::vec3* out, RayStats& stats);

// "getNearestDist" (every shape, the seed's name) for the frame of u, scalar and in lanes, for
// `sdfreel bench --micro`.
std::vector<DistanceFunction> beamsDistanceFunctions(const BeamsUniforms& u);

}  // namespace sdfreel::light_beams
