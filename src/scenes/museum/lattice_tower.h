#pragma once
// Exhibit 4's object: an open lattice tower (after Sol LeWitt's open modular structures) of
// slender white bars on the fourth plinth, which stands in the sun before the window. Seen from
// the hall against the window, its bars cut the sky into the gaps that the crepuscular pass
// (museum/atmosphere.h) draws out into shafts of shadow in the air, and in the sun it lays its
// grid's shadow across the plinth and the floor: the exhibit that shows the light. Built of the
// hall's boxes (drawn, shadowed and reflected as the hall is).
#include <glm/glm.hpp>
#include <vector>

#include "scenes/museum/hall_layout.h"

namespace sdfreel::museum {

const glm::ivec3 LATTICE_CELLS(2, 4, 2);  // cubic cells along x, y (up) and z
constexpr float LATTICE_CELL = 0.25f;     // a cell's side, metres, bar centre to bar centre
constexpr float LATTICE_BAR = 0.03f;      // bar thickness
// Raised off the plinth top so the bars' lowest faces do not lie in its plane (a tie that each
// rasteriser breaks its own way).
constexpr float LATTICE_GAP = 0.002f;

// The number of bars: one along each axis through every node of the other two.
int lattice_bar_count();

// Appends the tower's bars standing centred on the plinth top `top`.
void add_lattice_tower(std::vector<HallBox>& boxes, const glm::vec3& top);

}  // namespace sdfreel::museum
