#pragma once
// sdf_morph geometry: a torus that morphs into a mug, standing on a pedestal. World units are
// metres-ish, +Y up, the floor is y = 0 (handled analytically by the renderer, not in the SDF).
// Object space has its origin on the pedestal top, under the object's centre.
#include <glm/glm.hpp>

#include "scenes/scene.h"
#include "scenes/sdf_morph_uniforms.h"
#include "sdf/det_math.h"
#include "sdf/sdf.h"

namespace sdfreel::sdf_morph {

// ---- pedestal ----
constexpr float PEDESTAL_HALF_WIDTH = 0.62f;
constexpr float PEDESTAL_HEIGHT = 0.42f;
constexpr float PEDESTAL_CORNER = 0.04f;

// ---- torus: standing upright, its ring in the object's xy plane ----
constexpr float TORUS_MAJOR = 0.38f;
constexpr float TORUS_MINOR = 0.15f;
constexpr float TORUS_CENTER_Y = TORUS_MAJOR + TORUS_MINOR;  // resting on the pedestal

// ---- mug: a hollow cylinder with a rounded rim and a half-ring handle towards +x ----
constexpr float MUG_RADIUS = 0.34f;
constexpr float MUG_HALF_HEIGHT = 0.38f;
constexpr float MUG_WALL = 0.05f;
constexpr float MUG_BOTTOM = 0.06f;           // thickness of the mug's floor
constexpr float MUG_ROUNDING = 0.02f;         // radius of the rim and the outer edges
constexpr float MUG_CAVITY_OVERSHOOT = 0.2f;  // the cavity reaches above the rim: open top
constexpr float HANDLE_RADIUS = 0.2f;
constexpr float HANDLE_THICKNESS = 0.045f;
constexpr float HANDLE_Y = 0.03f;                         // above the mug's mid-height
constexpr float HANDLE_X = MUG_RADIUS - 0.5f * MUG_WALL;  // ends sit in the middle of the wall
constexpr float HANDLE_ARC_SIN = 1.0f;  // sin and cos of the arc half-angle (90 deg: half ring)
constexpr float HANDLE_ARC_COS = 0.0f;
constexpr float HANDLE_BLEND = 0.03f;  // smooth union radius where the handle meets the body

// ---- bounds ----
// Every morph stage lies inside this sphere (object space centre (0, y, 0); the rotation is
// about the y axis, so the world centre is fixed).
constexpr float OBJECT_BOUND_Y = PEDESTAL_HEIGHT + TORUS_CENTER_Y;
constexpr float OBJECT_BOUND_RADIUS = 0.68f;
// Within this distance of the object's bounding sphere its exact distance is evaluated; beyond it
// the sphere's distance stands in (a lower bound: cheap steps far away). It covers the reach of
// ambient occlusion, which needs exact values; soft shadows widen it further (see softShadow).
constexpr float OBJECT_BOUND_MARGIN = 0.15f;
// Sphere around object and pedestal: rays and shadow rays are marched only inside it.
constexpr float GROUP_BOUND_Y = 0.75f;
constexpr float GROUP_BOUND_RADIUS = 1.2f;

inline glm::vec3 objectBoundCenter() {
  return glm::vec3(0.0f, OBJECT_BOUND_Y, 0.0f);
}
inline glm::vec3 groupBoundCenter() {
  return glm::vec3(0.0f, GROUP_BOUND_Y, 0.0f);
}

// World -> object space: onto the pedestal top, then the frame's rotation about +Y.
inline glm::vec3 toObjectSpace(const glm::vec3& p, const MorphUniforms& u) {
  return rotateY(p - glm::vec3(0.0f, PEDESTAL_HEIGHT, 0.0f), u.rot_cos, u.rot_sin);
}

inline float mapTorus(const glm::vec3& q) {
  // sdTorus lies in xz; swap y and z to stand it up.
  return sdTorus(glm::vec3(q.x, q.z, q.y - TORUS_CENTER_Y), glm::vec2(TORUS_MAJOR, TORUS_MINOR));
}

inline float mapMug(const glm::vec3& q) {
  const glm::vec3 m = q - glm::vec3(0.0f, MUG_HALF_HEIGHT, 0.0f);  // origin at the mug's centre
  // The cup: shrink the solid and grow the cavity by the rounding radius, cut one from the
  // other, then grow the result back: a wall of MUG_WALL with rounded rim and edges.
  const float outer =
      sdCappedCylinder(m, MUG_HALF_HEIGHT - MUG_ROUNDING, MUG_RADIUS - MUG_ROUNDING);
  const float cavity_bottom = -MUG_HALF_HEIGHT + MUG_BOTTOM;
  const float cavity_top = MUG_HALF_HEIGHT + MUG_CAVITY_OVERSHOOT;
  const glm::vec3 c = m - glm::vec3(0.0f, 0.5f * (cavity_bottom + cavity_top), 0.0f);
  const float cavity =
      sdCappedCylinder(c, 0.5f * (cavity_top - cavity_bottom), MUG_RADIUS - MUG_WALL);
  const float cup = opRound(opSubtraction(cavity - MUG_ROUNDING, outer), MUG_ROUNDING);
  // The handle: a half ring in the xy plane bulging towards +x (sdCappedTorus opens about +y:
  // swap x and y).
  const glm::vec3 h = m - glm::vec3(HANDLE_X, HANDLE_Y, 0.0f);
  const float handle =
      sdCappedTorus(glm::vec3(h.y, h.x, h.z), glm::vec2(HANDLE_ARC_SIN, HANDLE_ARC_COS),
                    HANDLE_RADIUS, HANDLE_THICKNESS);
  // Carve the cavity again so the handle's ends do not poke into it.
  return opSubtraction(cavity, opSmoothUnion(cup, handle, HANDLE_BLEND));
}

// The morph: a per-frame constant blend of two 1-Lipschitz distances is 1-Lipschitz, so plain
// sphere-tracing steps stay safe at every stage.
inline float mapObject(const glm::vec3& p, const MorphUniforms& u) {
  const glm::vec3 q = toObjectSpace(p, u);
  if (u.morph <= 0.0f) return mapTorus(q);
  if (u.morph >= 1.0f) return mapMug(q);
  return dm::mix(mapTorus(q), mapMug(q), u.morph);
}

inline float mapPedestal(const glm::vec3& p) {
  const glm::vec3 c(0.0f, 0.5f * PEDESTAL_HEIGHT, 0.0f);
  return sdRoundBox(p - c,
                    glm::vec3(PEDESTAL_HALF_WIDTH, 0.5f * PEDESTAL_HEIGHT, PEDESTAL_HALF_WIDTH),
                    PEDESTAL_CORNER);
}

// Distance to object and pedestal, exact within `margin` of the object's bounding sphere; beyond
// it the sphere's distance stands in for the object's (a lower bound). `exact` tells which.
// The naive preset uses no bounding volume: always the exact distance.
inline float mapSceneBounded(const glm::vec3& p, const MorphUniforms& u, float margin,
                             bool& exact) {
  const float pedestal = mapPedestal(p);
  if (u.naive) {
    exact = true;
    return opUnion(mapObject(p, u), pedestal);
  }
  const float bound = glm::length(p - objectBoundCenter()) - OBJECT_BOUND_RADIUS;
  if (bound > margin) {
    exact = pedestal <= bound;
    return opUnion(bound, pedestal);
  }
  exact = true;
  return opUnion(mapObject(p, u), pedestal);
}

// Everything that casts shadows and is ray marched: object and pedestal.
inline float mapScene(const glm::vec3& p, const MorphUniforms& u, RayStats& stats) {
  stats.sdf_evals += 1;
  bool exact;
  return mapSceneBounded(p, u, OBJECT_BOUND_MARGIN, exact);
}

// At a hit point: is it the object (true) or the pedestal?
inline bool isObject(const glm::vec3& p, const MorphUniforms& u) {
  const float bound = glm::length(p - objectBoundCenter()) - OBJECT_BOUND_RADIUS;
  const float object = bound > OBJECT_BOUND_MARGIN ? bound : mapObject(p, u);
  return object <= mapPedestal(p);
}

}  // namespace sdfreel::sdf_morph
