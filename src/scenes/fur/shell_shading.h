#pragma once
// The C++ twins of shaders/fur/shell.vert and shaders/fur/shell.glsl: where a vertex of shell h
// goes, and the colour of a shell fragment (alpha 0 = discarded strand gap).
#include <glm/glm.hpp>

#include "render/frame_plan.h"

namespace sdfreel::fur {

// Strand heights: a cell's strand reaches h = mix(STRAND_MIN, STRAND_MAX, random).
constexpr float STRAND_MIN = 0.35f, STRAND_MAX = 1.0f;

// Per shape and frame, world space (uniforms u_fur_* on GL).
struct ShellMotion {
  float length = 0.0f;     // extrusion of the outermost shell
  glm::vec3 centre{0.0f};  // the body's centre, which the twist turns about
  glm::mat3 twist{1.0f};   // R of the seed's mix(V, R V, k)
  glm::vec3 offset{0.0f};  // strength * D
};

struct ShellLook {
  float density = 1.0f, thickness = 1.0f;
  glm::vec3 base{0.0f}, tip{0.0f};
  glm::vec3 light_dir{0.0f, 1.0f, 0.0f}, light{1.0f}, ambient{0.0f};
  float hit_id = -1.0f;  // >= 0: draw this id instead of the colour (MarchSettings::hit_mask)
  int surface = 0;       // MarchSettings::surface: draw the distance from `eye` or the normal
  glm::vec3 eye{0.0f};
};

// Instance data of shell i of n: (h, fake AO, physics weight k, i), constant per shell.
glm::vec4 shell_data(int i, int n, float curvature);

PlacedVertex place_shell_vertex(const ShellMotion& m, const MeshInstance& inst,
                                const glm::vec3& position, const glm::vec3& normal);
glm::vec4 shade_shell(const ShellLook& look, const MeshFragment& f);

}  // namespace sdfreel::fur
