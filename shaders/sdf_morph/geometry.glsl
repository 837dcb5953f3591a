// sdf_morph geometry: the twin of src/scenes/sdf_morph/geometry.h (same names and order).
#include "common/sdf.glsl"
#include "common/frame.glsl"
#include "sdf_morph/uniforms.glsl"

// ---- pedestal ----
const float PEDESTAL_HALF_WIDTH = 0.62;
const float PEDESTAL_HEIGHT = 0.42;
const float PEDESTAL_CORNER = 0.04;

// ---- torus ----
const float TORUS_MAJOR = 0.38;
const float TORUS_MINOR = 0.15;
const float TORUS_CENTER_Y = TORUS_MAJOR + TORUS_MINOR;

// ---- mug ----
const float MUG_RADIUS = 0.34;
const float MUG_HALF_HEIGHT = 0.38;
const float MUG_WALL = 0.05;
const float MUG_BOTTOM = 0.06;
const float MUG_ROUNDING = 0.02;
const float MUG_CAVITY_OVERSHOOT = 0.2;
const float HANDLE_RADIUS = 0.2;
const float HANDLE_THICKNESS = 0.045;
const float HANDLE_Y = 0.03;
const float HANDLE_X = MUG_RADIUS - 0.5 * MUG_WALL;
const float HANDLE_ARC_SIN = 1.0;
const float HANDLE_ARC_COS = 0.0;
const float HANDLE_BLEND = 0.03;

// ---- bounds ----
const float OBJECT_BOUND_Y = PEDESTAL_HEIGHT + TORUS_CENTER_Y;
const float OBJECT_BOUND_RADIUS = 0.68;
const float OBJECT_BOUND_MARGIN = 0.15;
const float GROUP_BOUND_Y = 0.75;
const float GROUP_BOUND_RADIUS = 1.2;

vec3 objectBoundCenter() {
  precise vec3 r_ = vec3(0.0, OBJECT_BOUND_Y, 0.0);
  return r_;
}
vec3 groupBoundCenter() {
  precise vec3 r_ = vec3(0.0, GROUP_BOUND_Y, 0.0);
  return r_;
}

vec3 toObjectSpace(vec3 p, MorphUniforms u) {
  precise vec3 lifted = p - vec3(0.0, PEDESTAL_HEIGHT, 0.0);
  precise vec3 r = rotateY(lifted, u.rot_cos, u.rot_sin);
  return r;
}

float mapTorus(vec3 q) {
  precise vec3 t = vec3(q.x, q.z, q.y - TORUS_CENTER_Y);
  precise float r = sdTorus(t, vec2(TORUS_MAJOR, TORUS_MINOR));
  return r;
}

float mapMug(vec3 q) {
  precise vec3 m = q - vec3(0.0, MUG_HALF_HEIGHT, 0.0);
  precise float outer =
      sdCappedCylinder(m, MUG_HALF_HEIGHT - MUG_ROUNDING, MUG_RADIUS - MUG_ROUNDING);
  precise float cavity_bottom = -MUG_HALF_HEIGHT + MUG_BOTTOM;
  precise float cavity_top = MUG_HALF_HEIGHT + MUG_CAVITY_OVERSHOOT;
  precise vec3 c = m - vec3(0.0, 0.5 * (cavity_bottom + cavity_top), 0.0);
  precise float cavity =
      sdCappedCylinder(c, 0.5 * (cavity_top - cavity_bottom), MUG_RADIUS - MUG_WALL);
  precise float cup = opRound(opSubtraction(cavity - MUG_ROUNDING, outer), MUG_ROUNDING);
  precise vec3 h = m - vec3(HANDLE_X, HANDLE_Y, 0.0);
  precise float handle = sdCappedTorus(vec3(h.y, h.x, h.z), vec2(HANDLE_ARC_SIN, HANDLE_ARC_COS),
                               HANDLE_RADIUS, HANDLE_THICKNESS);
  precise float r_ = opSubtraction(cavity, opSmoothUnion(cup, handle, HANDLE_BLEND));
  return r_;
}

float mapObject(vec3 p, MorphUniforms u) {
  precise vec3 q = toObjectSpace(p, u);
  if (u.morph <= 0.0) { precise float r_ = mapTorus(q); return r_; }
  if (u.morph >= 1.0) { precise float r_ = mapMug(q); return r_; }
  precise float r_ = dm_mix(mapTorus(q), mapMug(q), u.morph);
  return r_;
}

float mapPedestal(vec3 p) {
  precise vec3 c = vec3(0.0, 0.5 * PEDESTAL_HEIGHT, 0.0);
  return sdRoundBox(p - c, vec3(PEDESTAL_HALF_WIDTH, 0.5 * PEDESTAL_HEIGHT, PEDESTAL_HALF_WIDTH),
                    PEDESTAL_CORNER);
}

// The naive preset uses no bounding volume: always the exact distance.
float mapSceneBounded(vec3 p, MorphUniforms u, float margin, out bool exact) {
  precise float pedestal = mapPedestal(p);
  if (u.naive != 0) {
    exact = true;
    precise float r_ = opUnion(mapObject(p, u), pedestal);
    return r_;
  }
  precise float bound = dm_length(p - objectBoundCenter()) - OBJECT_BOUND_RADIUS;
  if (bound > margin) {
    exact = pedestal <= bound;
    precise float r_ = opUnion(bound, pedestal);
    return r_;
  }
  exact = true;
  precise float r_ = opUnion(mapObject(p, u), pedestal);
  return r_;
}

float mapScene(vec3 p, MorphUniforms u, inout RayStats stats) {
  stats.sdf_evals += 1u;
  bool exact;
  precise float r_ = mapSceneBounded(p, u, OBJECT_BOUND_MARGIN, exact);
  return r_;
}

bool isObject(vec3 p, MorphUniforms u) {
  precise float bound = dm_length(p - objectBoundCenter()) - OBJECT_BOUND_RADIUS;
  precise float object = bound > OBJECT_BOUND_MARGIN ? bound : mapObject(p, u);
  return object <= mapPedestal(p);
}
