#pragma once
// Periodic fractal value noise on the unit torus (period 1 in x and y): tiling generated textures
// (lantern_festival's paper maps). A pure function of its seed.
#include <cstdint>

namespace sdfreel {

// `octaves` layers starting at `cells` lattice cells per period.
float periodic_fbm(float x, float y, int cells, int octaves, uint32_t seed);

// The same with separate lattice sizes in x and y (stretched lattices make fibres).
float periodic_fbm2(float x, float y, int cells_x, int cells_y, int octaves, uint32_t seed);

}  // namespace sdfreel
