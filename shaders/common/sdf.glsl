// Signed distance primitives and operators: the twin of src/sdf/sdf.h (same names, arguments and
// order of operations; glm::length/dot/max become dm_length/dm_dot/dm_max).
#include "common/det_math.glsl"

// ---- helpers ----

const float SAFE_NORMALIZE_MIN_LENGTH2 = 1e-30;

vec3 safe_normalize(vec3 v) {
  precise float len2 = dm_dot(v, v);
  if (!(len2 > SAFE_NORMALIZE_MIN_LENGTH2)) { precise vec3 r_ = vec3(0.0, 1.0, 0.0); return r_; }
  precise vec3 r_ = v / sqrt(len2);
  return r_;
}

float dot2(vec2 v) {
  precise float r_ = dm_dot(v, v);
  return r_;
}
float dot2(vec3 v) {
  precise float r_ = dm_dot(v, v);
  return r_;
}

vec3 rotateY(vec3 p, float c, float s) {
  precise vec3 r = vec3(c * p.x + s * p.z, p.y, c * p.z - s * p.x);
  return r;
}

// ---- 3D primitives ----

float sdSphere(vec3 p, float r) {
  precise float r_ = dm_length(p) - r;
  return r_;
}

float sdBox(vec3 p, vec3 b) {
  precise vec3 q = abs(p) - b;
  precise float r_ = dm_length(dm_max(q, 0.0)) + dm_min(dm_max(q.x, dm_max(q.y, q.z)), 0.0);
  return r_;
}

float sdRoundBox(vec3 p, vec3 b, float r) {
  precise vec3 q = abs(p) - b + r;
  precise float r_ = dm_length(dm_max(q, 0.0)) + dm_min(dm_max(q.x, dm_max(q.y, q.z)), 0.0) - r;
  return r_;
}

float sdTorus(vec3 p, vec2 t) {
  precise vec2 q = vec2(dm_length(vec2(p.x, p.z)) - t.x, p.y);
  precise float r = dm_length(q) - t.y;
  return r;
}

float sdCappedTorus(vec3 p, vec2 sc, float ra, float rb) {
  p.x = abs(p.x);
  precise vec2 pxy = vec2(p.x, p.y);
  precise float k = (sc.y * p.x > sc.x * p.y) ? dm_dot(pxy, sc) : dm_length(pxy);
  precise float r_ = sqrt(dm_max(dm_dot(p, p) + ra * ra - 2.0 * ra * k, 0.0)) - rb;
  return r_;
}

float sdCappedCylinder(vec3 p, float h, float r) {
  precise vec2 d = abs(vec2(dm_length(vec2(p.x, p.z)), p.y)) - vec2(r, h);
  precise float r_ = dm_min(dm_max(d.x, d.y), 0.0) + dm_length(dm_max(d, 0.0));
  return r_;
}

float sdCappedCylinderOffset(vec3 p, float h, float r, vec2 offset) {
  precise float r_ = sdCappedCylinder(p - vec3(offset.x, 0.0, offset.y), h, r);
  return r_;
}

float sdPlane(vec3 p, vec3 n, float h) {
  precise float r_ = dm_dot(p, n) + h;
  return r_;
}

float sdSegment(vec3 p, vec3 a, vec3 b) {
  precise vec3 pa = p - a, ba = b - a;
  precise float bb = dm_dot(ba, ba);
  precise float h = bb > 0.0 ? dm_clamp(dm_dot(pa, ba) / bb, 0.0, 1.0) : 0.0;
  precise float r_ = dm_length(pa - ba * h);
  return r_;
}

float sdCapsule(vec3 p, vec3 a, vec3 b, float r) {
  precise float r_ = sdSegment(p, a, b) - r;
  return r_;
}

// ---- 2D primitives ----

float sdCircle(vec2 p, float r) {
  precise float r_ = dm_length(p) - r;
  return r_;
}

float sdSegment(vec2 p, vec2 a, vec2 b) {
  precise vec2 pa = p - a, ba = b - a;
  precise float bb = dm_dot(ba, ba);
  precise float h = bb > 0.0 ? dm_clamp(dm_dot(pa, ba) / bb, 0.0, 1.0) : 0.0;
  precise float r_ = dm_length(pa - ba * h);
  return r_;
}

float sdBox2(vec2 p, vec2 b) {
  precise vec2 q = abs(p) - b;
  precise float r_ = dm_length(dm_max(q, 0.0)) + dm_min(dm_max(q.x, q.y), 0.0);
  return r_;
}

float sdRoundRect(vec2 p, vec2 b, float r) {
  precise float r_ = sdBox2(p, b - vec2(r)) - r;
  return r_;
}

// ---- operators ----

float opUnion(float d1, float d2) {
  precise float r_ = dm_min(d1, d2);
  return r_;
}
float opSubtraction(float d1, float d2) {
  precise float r_ = dm_max(-d1, d2);
  return r_;
}
float opIntersection(float d1, float d2) {
  precise float r_ = dm_max(d1, d2);
  return r_;
}

float opSmoothUnion(float d1, float d2, float k) {
  if (!(k > 0.0)) { precise float r_ = opUnion(d1, d2); return r_; }
  precise float h = dm_clamp(0.5 + 0.5 * (d2 - d1) / k, 0.0, 1.0);
  precise float r_ = dm_mix(d2, d1, h) - k * h * (1.0 - h);
  return r_;
}

float opSmoothSubtraction(float d1, float d2, float k) {
  if (!(k > 0.0)) { precise float r_ = opSubtraction(d1, d2); return r_; }
  precise float h = dm_clamp(0.5 - 0.5 * (d2 + d1) / k, 0.0, 1.0);
  precise float r_ = dm_mix(d2, -d1, h) + k * h * (1.0 - h);
  return r_;
}

float opSmoothIntersection(float d1, float d2, float k) {
  if (!(k > 0.0)) { precise float r_ = opIntersection(d1, d2); return r_; }
  precise float h = dm_clamp(0.5 - 0.5 * (d2 - d1) / k, 0.0, 1.0);
  precise float r_ = dm_mix(d2, d1, h) + k * h * (1.0 - h);
  return r_;
}

float opOnion(float d, float t) {
  precise float r_ = abs(d) - t;
  return r_;
}
float opRound(float d, float r) {
  precise float r_ = d - r;
  return r_;
}
vec3 opSymXZ(vec3 p) {
  precise vec3 r_ = vec3(abs(p.x), p.y, abs(p.z));
  return r_;
}
