#pragma once
// water_lily's secondary rays in eight lanes: the soft shadows and the water's reflection march of
// up to eight pixels of a packet at once (render.h, SecondaryRays), each lane the scalar code's
// operations in its order: same bits, same RayStats as traceSecondary.
#include "scenes/scene.h"
#include "scenes/water_lily/render.h"
#include "scenes/water_lily/uniforms.h"
#include "sdf/lanes.h"

namespace sdfreel::water_lily {

// traceSecondary(rays[i], u, stats) for i < count (count <= LANES).
void traceSecondaryLanes(SecondaryRays* rays, int count, const LilyUniforms& u, RayStats& stats);

// softShadow (render.h) from each lane's origin in `active`, towards ld; 1 in the other lanes.
F8 softShadowLanes(const V3x8& ro, const glm::vec3& ld, float k, int steps, M8 active,
                   const LilyUniforms& u, RayStats& stats);

// mapScene(p, leaves, u).d in lanes, parts beyond `margin` as their bounds (lanes.cpp).
F8 mapDistanceLanes(const V3x8& p, const LilyUniforms& u, float margin, bool leaves);

}  // namespace sdfreel::water_lily
