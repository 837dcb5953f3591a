#pragma once
// water_lily in eight lanes: the CPU backend's packet path. The primary rays of a packet are
// marched together on V3x8 (the geometry templates of geometry.h, the scalar operations in the
// scalar order); so are their soft shadows and the water's reflection marches
// (secondary_lanes.h). Normals, materials and lighting run lane by lane with the scalar code
// (render.h: shadeBegin, shadeEnd). Same bits, same RayStats.
#include <glm/glm.hpp>
#include <vector>

#include "scenes/scene.h"
#include "scenes/water_lily/uniforms.h"

namespace sdfreel::water_lily {

// out[i] == sceneRadiance(rays.ray(i), u, stats) for i < rays.count, adding the same stats.
void radiancePacket(const RayPacket& rays, const LilyUniforms& u, glm::vec3* out, RayStats& stats);

// "mapScene" (flowers and pads with their bounds: what the marches evaluate) and "lilyFlower"
// (flower 0 alone) for the frame of u, scalar and in lanes.
std::vector<DistanceFunction> lilyDistanceFunctions(const LilyUniforms& u);

}  // namespace sdfreel::water_lily
