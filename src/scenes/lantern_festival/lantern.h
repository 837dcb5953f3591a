#pragma once
// One lantern of seed 000 in its own frame (y up, base on y = -1, top rim at y = +1), from three
// parts with the seed's shapes and sizes: paper (a cylinder shell 0.75 wide, open at the top), wood
// (a thin square base) and metal (two rings and four struts). Shading picks the part nearest to
// the hit point.
#include <glm/glm.hpp>

#include "sdf/sdf.h"

namespace sdfreel::lantern_festival {

// The part functions are templates over the point type (glm::vec3 or V3x8, like sdf/sdf.h): one
// source for the scalar path and the eight-lane path, with the same bits.

// Box minus the onion (0.03 shell) of a capped cylinder: the box (y from 1 to 5) cuts the top cap
// off.
template <class V>
inline auto sdfPaper(V p) {
  p = p - glm::vec3(0.0f, -1.0f, 0.0f);
  const auto box = sdBox(p - glm::vec3(0.0f, 4.0f, 0.0f), glm::vec3(2.0f));
  const auto cylinder = sdCappedCylinder(p - glm::vec3(0.0f, 1.5f, 0.0f), 1.5f, 0.75f);
  const auto cylinder_boundary = opOnion(cylinder, 0.03f);
  return opSubtraction(box, cylinder_boundary);
}

template <class V>
inline auto sdfWood(V p) {
  p.y += 1.0f;
  return sdBox(p, glm::vec3(1.1f, 0.04f, 1.1f));
}

// 0.75 * 0.707: the struts stand on the rings' diagonals.
constexpr float STRUT_OFFSET = 0.75f * 0.707f;

template <class V>
inline auto sdfMetal(V p) {
  p = p - glm::vec3(0.0f, -1.0f, 0.0f);
  const auto torus1 = sdTorus(p + glm::vec3(0.0f, -0.08f, 0.0f), glm::vec2(0.75f, 0.05f));
  const auto torus2 = sdTorus(p + glm::vec3(0.0f, -2.0f, 0.0f), glm::vec2(0.75f, 0.05f));
  const auto tori = opUnion(torus1, torus2);
  const auto cylindri = sdCappedCylinderOffset(opSymXZ(p + glm::vec3(0.0f, -1.0f, 0.0f)), 1.03f,
                                               0.05f, glm::vec2(STRUT_OFFSET));
  return opSmoothUnion(cylindri, tori, 0.1f);
}

template <class V>
inline auto sdfLantern(const V& p) {
  return opUnion(opUnion(sdfPaper(p), sdfWood(p)), sdfMetal(p));
}

enum class LanternPart { Paper, Wood, Metal };

// The seed's material choice: metal or paper where strictly nearest, wood otherwise.
inline LanternPart nearestPart(const glm::vec3& p) {
  const float dPaper = sdfPaper(p), dWood = sdfWood(p), dMetal = sdfMetal(p);
  if (dMetal < dPaper && dMetal < dWood) return LanternPart::Metal;
  if (dPaper < dMetal && dPaper < dWood) return LanternPart::Paper;
  return LanternPart::Wood;
}

// Bounding cylinder of the lantern in its own frame: the wood base's corners reach
// sqrt(2) * 1.1 = 1.556 from the axis; y spans -1.04 (base) .. 1.05 (top ring), and the smooth
// union adds at most k/4 = 0.025. Rounded up.
constexpr float LANTERN_BOUND_RADIUS = 1.56f;
constexpr float LANTERN_BOUND_HALF_HEIGHT = 1.08f;

}  // namespace sdfreel::lantern_festival
