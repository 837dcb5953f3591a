#pragma once
// sdf_morph geometry: a torus that morphs into a mug, standing on a pedestal. World units are
// metres-ish, +Y up, the floor is y = 0 (handled analytically by the renderer, not in the SDF).
// Object space has its origin on the pedestal top, under the object's centre.
#include <glm/glm.hpp>
#include <utility>

#include "scenes/scene.h"
#include "scenes/sdf_morph/uniforms.h"
#include "sdf/det_math.h"
#include "sdf/lanes.h"
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

// Scalar (glm::vec3) or eight lanes (V3x8): the distance type and its mask type.
template <class V>
using DistanceOf = decltype(vlength(std::declval<V>()));
template <class V>
using MaskOf = decltype(DistanceOf<V>() < DistanceOf<V>());

// A mask with every lane set (scalar: true), and a select of masks.
inline bool allLanes(float) {
  return true;
}
inline M8 allLanes(F8) {
  return splat_mask(true);
}
inline bool selectMask(bool m, bool a, bool b) {
  return m ? a : b;
}
inline M8 selectMask(M8 m, M8 a, M8 b) {
  return select(m, a, b);
}

// The geometry below is one source for both paths (templates like sdf/sdf.h): branches on the
// per-frame uniforms stay plain ifs, branches on the point become selects of both sides.

// World -> object space: onto the pedestal top, then the frame's rotation about +Y.
template <class V>
inline V toObjectSpace(const V& p, const MorphUniforms& u) {
  return rotateY(p - glm::vec3(0.0f, PEDESTAL_HEIGHT, 0.0f), u.rot_cos, u.rot_sin);
}

template <class V>
inline auto mapTorus(const V& q) {
  // sdTorus lies in xz; swap y and z to stand it up.
  return sdTorus(vec3_of(q.x, q.z, q.y - TORUS_CENTER_Y), glm::vec2(TORUS_MAJOR, TORUS_MINOR));
}

template <class V>
inline auto mapMug(const V& q) {
  const V m = q - glm::vec3(0.0f, MUG_HALF_HEIGHT, 0.0f);  // origin at the mug's centre
  // The cup: shrink the solid and grow the cavity by the rounding radius, cut one from the
  // other, then grow the result back: a wall of MUG_WALL with rounded rim and edges.
  const auto outer = sdCappedCylinder(m, MUG_HALF_HEIGHT - MUG_ROUNDING, MUG_RADIUS - MUG_ROUNDING);
  const float cavity_bottom = -MUG_HALF_HEIGHT + MUG_BOTTOM;
  const float cavity_top = MUG_HALF_HEIGHT + MUG_CAVITY_OVERSHOOT;
  const V c = m - glm::vec3(0.0f, 0.5f * (cavity_bottom + cavity_top), 0.0f);
  const auto cavity =
      sdCappedCylinder(c, 0.5f * (cavity_top - cavity_bottom), MUG_RADIUS - MUG_WALL);
  const auto cup = opRound(opSubtraction(cavity - MUG_ROUNDING, outer), MUG_ROUNDING);
  // The handle: a half ring in the xy plane bulging towards +x (sdCappedTorus opens about +y:
  // swap x and y).
  const V h = m - glm::vec3(HANDLE_X, HANDLE_Y, 0.0f);
  const auto handle =
      sdCappedTorus(vec3_of(h.y, h.x, h.z), glm::vec2(HANDLE_ARC_SIN, HANDLE_ARC_COS),
                    HANDLE_RADIUS, HANDLE_THICKNESS);
  // Carve the cavity again so the handle's ends do not poke into it.
  return opSubtraction(cavity, opSmoothUnion(cup, handle, HANDLE_BLEND));
}

// The morph: a per-frame constant blend of two 1-Lipschitz distances is 1-Lipschitz, so plain
// sphere-tracing steps stay safe at every stage.
template <class V>
inline auto mapObject(const V& p, const MorphUniforms& u) {
  const V q = toObjectSpace(p, u);
  if (u.morph <= 0.0f) return mapTorus(q);
  if (u.morph >= 1.0f) return mapMug(q);
  return dm::mix(mapTorus(q), mapMug(q), u.morph);
}

template <class V>
inline auto mapPedestal(const V& p) {
  const glm::vec3 c(0.0f, 0.5f * PEDESTAL_HEIGHT, 0.0f);
  return sdRoundBox(p - c,
                    glm::vec3(PEDESTAL_HALF_WIDTH, 0.5f * PEDESTAL_HEIGHT, PEDESTAL_HALF_WIDTH),
                    PEDESTAL_CORNER);
}

// Distance to object and pedestal, exact within `margin` of the object's bounding sphere; beyond
// it the sphere's distance stands in for the object's (a lower bound). `exact` tells which.
// The naive preset uses no bounding volume: always the exact distance. Lanes where the bound
// stands in skip the object only when all of them do (the selected bits are the same).
template <class V, class F>
inline DistanceOf<V> mapSceneBounded(const V& p, const MorphUniforms& u, F margin,
                                     MaskOf<V>& exact) {
  const DistanceOf<V> pedestal = mapPedestal(p);
  const MaskOf<V> all_exact = allLanes(pedestal);
  if (u.naive) {
    exact = all_exact;
    return opUnion(mapObject(p, u), pedestal);
  }
  const DistanceOf<V> bound = vlength(p - objectBoundCenter()) - OBJECT_BOUND_RADIUS;
  const MaskOf<V> far = bound > margin;
  const MaskOf<V> bound_exact = pedestal <= bound;
  if (all(far)) {
    exact = bound_exact;
    return opUnion(bound, pedestal);
  }
  exact = selectMask(far, bound_exact, all_exact);
  return select(far, opUnion(bound, pedestal), opUnion(mapObject(p, u), pedestal));
}

// Everything that casts shadows and is ray marched: object and pedestal.
inline float mapScene(const glm::vec3& p, const MorphUniforms& u, RayStats& stats) {
  stats.sdf_evals += 1;
  bool exact;
  return mapSceneBounded(p, u, OBJECT_BOUND_MARGIN, exact);
}

// At a hit point: is it the object (true) or the pedestal?
template <class V>
inline MaskOf<V> isObject(const V& p, const MorphUniforms& u) {
  const DistanceOf<V> bound = vlength(p - objectBoundCenter()) - OBJECT_BOUND_RADIUS;
  const MaskOf<V> far = bound > OBJECT_BOUND_MARGIN;
  DistanceOf<V> object = bound;
  if (!all(far)) object = select(far, bound, mapObject(p, u));
  return object <= mapPedestal(p);
}

}  // namespace sdfreel::sdf_morph
