#include "scenes/museum/hall_layout.h"

#include <algorithm>

#include "scenes/museum/lattice_tower.h"
#include "scenes/museum/paintings.h"
#include "sdf/sdf.h"

namespace sdfreel::museum {
namespace {

using glm::vec3;

const vec3 WALL_ALBEDO(0.72f, 0.70f, 0.66f);  // warm white plaster
constexpr float WALL_ROUGHNESS = 0.9f;
const vec3 CEILING_ALBEDO(0.8f, 0.8f, 0.78f);
const vec3 FLOOR_ALBEDO(0.42f, 0.30f, 0.19f);  // oak
const vec3 STONE_ALBEDO(0.62f, 0.61f, 0.58f);  // plinths
constexpr float STONE_ROUGHNESS = 0.35f;
const vec3 WOOD_DARK(0.18f, 0.11f, 0.07f);  // door, bench, frames
constexpr float WOOD_ROUGHNESS = 0.5f;
const vec3 LABEL_ALBEDO(0.85f, 0.84f, 0.8f);
constexpr float DOOR_X0 = 3.2f, DOOR_X1 = 4.6f, DOOR_H = 2.4f;

void add(std::vector<HallBox>& b, vec3 lo, vec3 hi, vec3 albedo, float material) {
  b.push_back({lo, hi, albedo, material});
}

void shell(std::vector<HallBox>& b) {
  const float X = ROOM_X, Z = ROOM_Z, H = ROOM_H, W = WALL;
  add(b, {-X - W, -W, -Z - W}, {X + W, 0, Z + W}, FLOOR_ALBEDO, MATERIAL_FLOOR);
  add(b, {-X - W, H, -Z - W}, {X + W, H + W, Z + W}, CEILING_ALBEDO, WALL_ROUGHNESS);
  add(b, {X, 0, -Z}, {X + W, H, Z}, WALL_ALBEDO, WALL_ROUGHNESS);          // east
  add(b, {-X - W, 0, Z}, {X + W, H, Z + W}, WALL_ALBEDO, WALL_ROUGHNESS);  // south
  // North wall around the door.
  add(b, {-X - W, 0, -Z - W}, {DOOR_X0, H, -Z}, WALL_ALBEDO, WALL_ROUGHNESS);
  add(b, {DOOR_X1, 0, -Z - W}, {X + W, H, -Z}, WALL_ALBEDO, WALL_ROUGHNESS);
  add(b, {DOOR_X0, DOOR_H, -Z - W}, {DOOR_X1, H, -Z}, WALL_ALBEDO, WALL_ROUGHNESS);
  add(b, {DOOR_X0, 0, -Z - 0.1f}, {DOOR_X1, DOOR_H, -Z - 0.05f}, WOOD_DARK, WOOD_ROUGHNESS);
  add(b, {DOOR_X0 - 0.1f, 0, -Z}, {DOOR_X0, DOOR_H + 0.1f, -Z + 0.04f}, WOOD_DARK, 0.5f);
  add(b, {DOOR_X1, 0, -Z}, {DOOR_X1 + 0.1f, DOOR_H + 0.1f, -Z + 0.04f}, WOOD_DARK, 0.5f);
  add(b, {DOOR_X0, DOOR_H, -Z}, {DOOR_X1, DOOR_H + 0.1f, -Z + 0.04f}, WOOD_DARK, 0.5f);
  add(b, {DOOR_X1 - 0.2f, 1.0f, -Z - 0.05f}, {DOOR_X1 - 0.12f, 1.08f, -Z + 0.02f},
      {0.6f, 0.5f, 0.3f}, 0.2f);  // handle
}

void west_wall_with_window(std::vector<HallBox>& b) {
  const float x0 = -ROOM_X - WALL, x1 = -ROOM_X;
  add(b, {x0, 0, -ROOM_Z}, {x1, WINDOW_Y0, ROOM_Z}, WALL_ALBEDO, WALL_ROUGHNESS);
  add(b, {x0, WINDOW_Y1, -ROOM_Z}, {x1, ROOM_H, ROOM_Z}, WALL_ALBEDO, WALL_ROUGHNESS);
  add(b, {x0, WINDOW_Y0, -ROOM_Z}, {x1, WINDOW_Y1, WINDOW_Z0}, WALL_ALBEDO, WALL_ROUGHNESS);
  add(b, {x0, WINDOW_Y0, WINDOW_Z1}, {x1, WINDOW_Y1, ROOM_Z}, WALL_ALBEDO, WALL_ROUGHNESS);
  const float h = MULLION_HALF, xm = x0 + 0.5f * WALL;
  add(b, {xm - h, WINDOW_Y0, MULLION_Z - h}, {xm + h, WINDOW_Y1, MULLION_Z + h}, WOOD_DARK, 0.5f);
  add(b, {xm - h, MULLION_Y - h, WINDOW_Z0}, {xm + h, MULLION_Y + h, WINDOW_Z1}, WOOD_DARK, 0.5f);
}

// Painting k in its frame on its long wall, with a label beside it.
void picture(std::vector<HallBox>& b, int k) {
  const Painting& p = painting(k);
  const float wall = p.side * ROOM_Z, in = -p.side;  // `in` points into the room
  auto slab = [&](float x0, float x1, float y0, float y1, float depth, vec3 c, float m) {
    const float z0 = wall, z1 = wall + in * depth;
    add(b, {x0, y0, glm::min(z0, z1)}, {x1, y1, glm::max(z0, z1)}, c, m);
  };
  slab(p.x - 0.7f, p.x + 0.7f, 1.3f, 2.4f, 0.05f, WOOD_DARK, WOOD_ROUGHNESS);
  slab(p.x - CANVAS_HALF_W, p.x + CANVAS_HALF_W, CANVAS_Y0, CANVAS_Y1, 0.06f, p.key,
       MATERIAL_PAINTING + float(k));
  slab(p.x + 0.85f, p.x + 1.15f, 1.45f, 1.6f, 0.02f, LABEL_ALBEDO, 0.6f);
}

void bench(std::vector<HallBox>& b) {
  const vec3 c(-0.4f, 0.0f, 0.0f);
  add(b, c + vec3(-0.8f, 0.42f, -0.25f), c + vec3(0.8f, 0.48f, 0.25f), WOOD_DARK, WOOD_ROUGHNESS);
  for (const float x : {-0.7f, 0.6f})
    add(b, c + vec3(x, 0.0f, -0.22f), c + vec3(x + 0.1f, 0.42f, 0.22f), {0.1f, 0.1f, 0.1f}, 0.3f);
}

void plinths(std::vector<HallBox>& b) {
  for (int i = 0; i < PLINTH_COUNT; ++i) {
    const vec3 base = plinth_base(i);
    add(b, base - vec3(PLINTH_HALF, 0.0f, PLINTH_HALF),
        base + vec3(PLINTH_HALF, PLINTH_H, PLINTH_HALF), STONE_ALBEDO, STONE_ROUGHNESS);
    // The exhibit's label on the plinth's face towards the hall's centre line, or, for the plinth
    // on that line, towards the door end.
    const int axis = base.z == 0.0f ? 0 : 2;
    const float in = axis == 0 ? 1.0f : (base.z < 0.0f ? 1.0f : -1.0f);
    const int across = 2 - axis;
    const float face = base[axis] + in * PLINTH_HALF;
    vec3 lo(0.0f, 0.75f, 0.0f), hi(0.0f, 0.85f, 0.0f);
    lo[axis] = glm::min(face, face + in * 0.02f), hi[axis] = glm::max(face, face + in * 0.02f);
    lo[across] = base[across] - 0.15f, hi[across] = base[across] + 0.15f;
    add(b, lo, hi, LABEL_ALBEDO, 0.6f);
  }
}

void exhibit_four(std::vector<HallBox>& b) {
  add_lattice_tower(b, plinth_base(LIGHT_PLINTH) + vec3(0.0f, PLINTH_H, 0.0f));
}

}  // namespace

glm::vec3 plinth_base(int index) {
  const glm::vec3 bases[PLINTH_COUNT] = {
      {-3.0f, 0.0f, -1.7f}, {-3.0f, 0.0f, 1.7f}, {1.8f, 0.0f, -1.7f}, {-5.2f, 0.0f, 0.0f}};
  return bases[index];
}

std::vector<HallBox> hall_boxes() {
  std::vector<HallBox> b;
  shell(b);
  west_wall_with_window(b);
  for (int k = 0; k < PAINTING_COUNT; ++k) picture(b, k);
  bench(b);
  plinths(b);
  exhibit_four(b);
  return b;
}

std::vector<HallBox> sun_casters() {
  std::vector<HallBox> b;
  west_wall_with_window(b);
  bench(b);
  plinths(b);
  exhibit_four(b);
  return b;
}

std::vector<HallBox> sun_occluders() {
  std::vector<HallBox> b;
  bench(b);
  for (int i = 0; i < PLINTH_COUNT; ++i) {
    const glm::vec3 base = plinth_base(i);
    add(b, base - glm::vec3(PLINTH_HALF, 0.0f, PLINTH_HALF),
        base + glm::vec3(PLINTH_HALF, PLINTH_H, PLINTH_HALF), STONE_ALBEDO, STONE_ROUGHNESS);
  }
  exhibit_four(b);
  return b;
}

float hall_distance(const glm::vec3& p) {
  static const std::vector<HallBox> boxes = hall_boxes();
  float d = 1e30f;
  for (const HallBox& b : boxes)
    d = std::min(d, sdBox(p - 0.5f * (b.lo + b.hi), 0.5f * (b.hi - b.lo)));
  return d;
}

}  // namespace sdfreel::museum
