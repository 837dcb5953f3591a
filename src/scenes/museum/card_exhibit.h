#pragma once
// Exhibit 2 on the second plinth: the lenticular card (scenes/lenticular_card/exhibit.h), stood on
// the plinth top and turned towards the hall's middle, drawn into the hall's colour and depth
// targets so the depth test composites it with the hall (both ways: the hall hides the card, the
// card hides what stands behind it).
#include "scenes/lenticular_card/textures.h"
#include "scenes/museum/exhibits.h"

namespace sdfreel::museum {

constexpr int CARD_PLINTH = 1;
constexpr float CARD_HIT_ID_BASE = 2.0f;  // the card's and stand's hit ids are 3 and 4 (museum.cpp)

// The card's pose in exhibit space (plinth top at the origin): turned about +y so its face looks
// across the hall and a little down it, towards where the walkthrough passes.
glm::mat4 card_pose();

// The card's passes for the plinth's ExhibitPasses slot. `prints` must outlive the plan's
// construction (the passes own the textures they read).
ExhibitPasses card_exhibit(const lenticular_card::CardPrints& prints);

}  // namespace sdfreel::museum
