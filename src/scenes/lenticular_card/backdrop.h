#pragma once
// The standalone scene's surroundings: a floor (y = 0) fading into a dim studio backdrop, with a
// soft contact shadow under the stand at the origin. GLSL twin shaders/lenticular_card/
// lenticular_card.glsl.
#include <glm/glm.hpp>

#include "render/rays.h"

namespace sdfreel::lenticular_card {

// hit_mask: 0 (nothing marched here), as MarchSettings::hit_mask asks; surface: the floor's
// distance or normal, or no surface beyond it, as MarchSettings::surface asks.
glm::vec3 backdrop(const Ray& ray, const glm::vec3& light, bool hit_mask, int surface);
// The same for a packet of eight rays from one origin, each lane the scalar function's bits.
V3x8 backdrop(const RayPacket& rays, const glm::vec3& light, bool hit_mask, int surface);

}  // namespace sdfreel::lenticular_card
