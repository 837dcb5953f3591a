#pragma once
// sdf_morph in eight lanes: the CPU backend's packet path. Marches, normals, soft shadows and
// ambient occlusion run on V3x8 with the scalar operations in the scalar order; the rest of the
// shading is the scalar code, lane by lane (sdf_morph/render.h phases). Same bits, same RayStats.
#include <glm/glm.hpp>
#include <vector>

#include "scenes/scene.h"
#include "scenes/sdf_morph/uniforms.h"

namespace sdfreel::sdf_morph {

// out[i] == sceneRadiance(rays.ray(i), u, stats) for i < rays.count, adding the same stats.
void radiance_lanes(const RayPacket& rays, const MorphUniforms& u, glm::vec3* out, RayStats& stats);

// "mapScene" (object with its bound, and pedestal: what the marches evaluate) and "mapObject"
// (the morphing object alone) for the frame of u, scalar and in lanes.
std::vector<DistanceFunction> morphDistanceFunctions(const MorphUniforms& u);

}  // namespace sdfreel::sdf_morph
