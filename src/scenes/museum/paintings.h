#pragma once
// The pictures on the hall's long walls: where each hangs, its colours, and what its canvas shows,
// a procedural landscape (a sky paling to the horizon, a low sun, three ridges of hills from
// smooth value noise, the canvas's grain), different for each picture and in its own colours. The
// hall's boxes hang them (museum/hall_layout.cpp) with the material MATERIAL_PAINTING + k; the
// hall's shading asks painting_albedo for the canvas's colour. GLSL twin:
// shaders/museum/paintings.glsl.
#include <glm/glm.hpp>

namespace sdfreel::museum {

constexpr int PAINTING_COUNT = 5;
constexpr float CANVAS_HALF_W = 0.6f, CANVAS_Y0 = 1.4f, CANVAS_Y1 = 2.3f;

struct Painting {
  float x;        // the canvas's centre along the wall
  float side;     // -1 the north wall (z = -ROOM_Z), +1 the south wall
  glm::vec3 key;  // its dominant colour (linear albedo)
};

const Painting& painting(int k);

// The albedo of canvas k at world point p (on its face): the landscape seen the right way round
// from the room.
glm::vec3 painting_albedo(const glm::vec3& p, int k);

}  // namespace sdfreel::museum
