#pragma once
// The museum hall as boxes (all of its geometry is one unit cube mesh, instanced): a room 12 m
// long (x), 8 m wide (z) and 4 m high, a tall window in the west wall (x = -6) through which the
// sun comes, a door in the north wall, a bench, four plinths, exhibit 4's lattice tower, picture
// frames and labels.
// World units are metres, +Y up, the floor is y = 0.
#include <glm/glm.hpp>
#include <vector>

namespace sdfreel::museum {

constexpr float ROOM_X = 6.0f;  // the interior spans x in [-ROOM_X, ROOM_X] ...
constexpr float ROOM_Z = 4.0f;  // ... z in [-ROOM_Z, ROOM_Z]
constexpr float ROOM_H = 4.0f;  // ... and y in [0, ROOM_H]
constexpr float WALL = 0.2f;    // walls, floor and ceiling thickness (outside the interior)

// The window's opening in the west wall (planes x = -ROOM_X and x = -ROOM_X - WALL) and its
// cross of mullions.
constexpr float WINDOW_Y0 = 1.5f, WINDOW_Y1 = 3.5f;
constexpr float WINDOW_Z0 = -1.3f, WINDOW_Z1 = 1.3f;
constexpr float MULLION_Y = 2.5f, MULLION_Z = 0.0f, MULLION_HALF = 0.05f;

constexpr float PLINTH_HALF = 0.35f;  // plinths are 0.7 x 1.0 x 0.7
constexpr float PLINTH_H = 1.0f;
constexpr int PLINTH_COUNT = 4;
// Plinth centres on the floor: exhibits 1 and 2 face each other across the hall halfway to the
// window, the fur case stands nearer the door, and exhibit 4's plinth stands in the sun before the
// window, on the hall's centre line.
glm::vec3 plinth_base(int index);
constexpr int LIGHT_PLINTH = 3;  // exhibit 4's (museum/lattice_tower.h)

// Material codes of HallBox::material (instance data w): roughness in [0, 1), or a pattern.
constexpr float MATERIAL_FLOOR = 2.0f;     // oak planks; roughness FLOOR_ROUGHNESS
constexpr float MATERIAL_PAINTING = 3.0f;  // + k: painting k's canvas (museum/paintings.h)

// An axis-aligned box of the hall with its material.
struct HallBox {
  glm::vec3 lo, hi;
  glm::vec3 albedo;  // linear Rec.709
  float material;    // roughness in [0, 1), MATERIAL_FLOOR or MATERIAL_PAINTING + k
};

// Every box of the hall, in a fixed order.
std::vector<HallBox> hall_boxes();

// Distance from p to the nearest box of the hall (negative inside one).
float hall_distance(const glm::vec3& p);

// The boxes that may stand between the sun and a sunlit point of the room: the west wall with its
// window and mullions, the bench, the plinths (and their labels). The sun's shadow map draws them
// (museum/sun_shadow.h).
std::vector<HallBox> sun_casters();

// The boxes inside the room that cast sun shadows (plinths, bench), for the analytic test of the
// reflection probe's shading (museum/lighting.h), which runs before the frame's shadow map exists.
std::vector<HallBox> sun_occluders();

}  // namespace sdfreel::museum
