#pragma once
// shadeCard for eight rays at once (src/sdf/lanes.h): each lane performs shadeCard's operations in
// its order, so it gives the same bits; branches are selects of both sides, texel reads one lane
// at a time. For the picture only: hit masks and surface outputs stay with shadeCard.
#include "scenes/lenticular_card/card.h"
#include "sdf/lanes.h"

namespace sdfreel::lenticular_card {

// The lanes whose rays hit the card or its stand, with their colours and hit distances t (other
// lanes' values are unspecified). Requires !u.hit_mask and u.surface == SURFACE_COLOUR.
M8 shadeCard_lanes(const RayPacket& rays, const CardUniforms& u, const CardTextures& tex,
                   V3x8& colour, F8& t);

}  // namespace sdfreel::lenticular_card
