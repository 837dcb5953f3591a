// Signed distance primitives and operators: the twin of src/sdf/sdf.h (same names, arguments and
// order of operations; glm::length/dot/max become dm_length/dm_dot/dm_max).
#include "common/det_math.glsl"

// ---- helpers ----

const float SAFE_NORMALIZE_MIN_LENGTH2 = 1e-30;

vec3 safe_normalize(vec3 v) {
  precise float len2 = dm_dot(v, v);
  if (!(len2 > SAFE_NORMALIZE_MIN_LENGTH2)) return vec3(0.0, 1.0, 0.0);
  return v / sqrt(len2);
}

float dot2(vec2 v) { return dm_dot(v, v); }
float dot2(vec3 v) { return dm_dot(v, v); }

vec3 rotateY(vec3 p, float c, float s) { return vec3(c * p.x + s * p.z, p.y, c * p.z - s * p.x); }

// ---- 3D primitives ----

float sdSphere(vec3 p, float r) { return dm_length(p) - r; }

float sdBox(vec3 p, vec3 b) {
  precise vec3 q = abs(p) - b;
  return dm_length(dm_max(q, 0.0)) + dm_min(dm_max(q.x, dm_max(q.y, q.z)), 0.0);
}

float sdRoundBox(vec3 p, vec3 b, float r) {
  precise vec3 q = abs(p) - b + r;
  return dm_length(dm_max(q, 0.0)) + dm_min(dm_max(q.x, dm_max(q.y, q.z)), 0.0) - r;
}

float sdTorus(vec3 p, vec2 t) {
  precise vec2 q = vec2(dm_length(vec2(p.x, p.z)) - t.x, p.y);
  return dm_length(q) - t.y;
}

float sdCappedTorus(vec3 p, vec2 sc, float ra, float rb) {
  p.x = abs(p.x);
  precise vec2 pxy = vec2(p.x, p.y);
  precise float k = (sc.y * p.x > sc.x * p.y) ? dm_dot(pxy, sc) : dm_length(pxy);
  return sqrt(dm_max(dm_dot(p, p) + ra * ra - 2.0 * ra * k, 0.0)) - rb;
}

float sdCappedCylinder(vec3 p, float h, float r) {
  precise vec2 d = abs(vec2(dm_length(vec2(p.x, p.z)), p.y)) - vec2(r, h);
  return dm_min(dm_max(d.x, d.y), 0.0) + dm_length(dm_max(d, 0.0));
}

float sdCappedCylinderOffset(vec3 p, float h, float r, vec2 offset) {
  return sdCappedCylinder(p - vec3(offset.x, 0.0, offset.y), h, r);
}

float sdPlane(vec3 p, vec3 n, float h) { return dm_dot(p, n) + h; }

float sdSegment(vec3 p, vec3 a, vec3 b) {
  precise vec3 pa = p - a, ba = b - a;
  precise float bb = dm_dot(ba, ba);
  precise float h = bb > 0.0 ? dm_clamp(dm_dot(pa, ba) / bb, 0.0, 1.0) : 0.0;
  return dm_length(pa - ba * h);
}

float sdCapsule(vec3 p, vec3 a, vec3 b, float r) { return sdSegment(p, a, b) - r; }

// ---- 2D primitives ----

float sdCircle(vec2 p, float r) { return dm_length(p) - r; }

float sdSegment(vec2 p, vec2 a, vec2 b) {
  precise vec2 pa = p - a, ba = b - a;
  precise float bb = dm_dot(ba, ba);
  precise float h = bb > 0.0 ? dm_clamp(dm_dot(pa, ba) / bb, 0.0, 1.0) : 0.0;
  return dm_length(pa - ba * h);
}

float sdBox2(vec2 p, vec2 b) {
  precise vec2 q = abs(p) - b;
  return dm_length(dm_max(q, 0.0)) + dm_min(dm_max(q.x, q.y), 0.0);
}

float sdRoundRect(vec2 p, vec2 b, float r) { return sdBox2(p, b - vec2(r)) - r; }

// ---- operators ----

float opUnion(float d1, float d2) { return dm_min(d1, d2); }
float opSubtraction(float d1, float d2) { return dm_max(-d1, d2); }
float opIntersection(float d1, float d2) { return dm_max(d1, d2); }

float opSmoothUnion(float d1, float d2, float k) {
  if (!(k > 0.0)) return opUnion(d1, d2);
  precise float h = dm_clamp(0.5 + 0.5 * (d2 - d1) / k, 0.0, 1.0);
  return dm_mix(d2, d1, h) - k * h * (1.0 - h);
}

float opSmoothSubtraction(float d1, float d2, float k) {
  if (!(k > 0.0)) return opSubtraction(d1, d2);
  precise float h = dm_clamp(0.5 - 0.5 * (d2 + d1) / k, 0.0, 1.0);
  return dm_mix(d2, -d1, h) + k * h * (1.0 - h);
}

float opSmoothIntersection(float d1, float d2, float k) {
  if (!(k > 0.0)) return opIntersection(d1, d2);
  precise float h = dm_clamp(0.5 - 0.5 * (d2 - d1) / k, 0.0, 1.0);
  return dm_mix(d2, d1, h) + k * h * (1.0 - h);
}

float opOnion(float d, float t) { return abs(d) - t; }
float opRound(float d, float r) { return d - r; }
vec3 opSymXZ(vec3 p) { return vec3(abs(p.x), p.y, abs(p.z)); }
