#pragma once
// light_beams: the seed's 2D shapes (circles, and line segments with a stroke) and what the
// shadows need of them: Quilez's 2D distance functions, the closest point, the angular span seen
// from a point, and where a ray first meets the shape. Small pure functions with the seed's
// names; shaders/light_beams/shapes.glsl is their line-for-line twin.
#include <glm/glm.hpp>

#include "sdf/det_math.h"

namespace sdfreel::light_beams {

using glm::vec2;

constexpr int SHAPE_CIRCLE = 0;
constexpr int SHAPE_SEGMENT = 1;
constexpr float NO_HIT = -1.0f;

// A circle (centre a, radius r) or a segment from a to b with stroke r: a capsule.
struct Shape {
  int type = SHAPE_CIRCLE;
  vec2 a{0.0f}, b{0.0f};
  float r = 0.0f;
};

// The GLSL order of operations, written out (glm's may differ from dm_dot's).
inline float dotv(vec2 a, vec2 b) {
  return a.x * b.x + a.y * b.y;
}
inline float crossv(vec2 a, vec2 b) {
  return a.x * b.y - a.y * b.x;
}
inline float lengthv(vec2 v) {
  return dm::sqrt(dotv(v, v));
}

// The seed's sphereSDF: distance(p, centre) - radius.
inline float circleSDF(vec2 p, vec2 c, float r) {
  return lengthv(p - c) - r;
}

// Where along a-b the point closest to p lies (0..1). Both ends equal: 0, the segment is a circle
// (tests/hard_cases/light_beams/segment_ends_equal).
inline float segmentParam(vec2 p, vec2 a, vec2 b) {
  const vec2 ba = b - a, pa = p - a;
  const float bb = dotv(ba, ba);
  return bb > 0.0f ? dm::clamp(dotv(pa, ba) / bb, 0.0f, 1.0f) : 0.0f;
}

// The seed's segmentSDF (Quilez): length(pa - h * ba) - stroke.
inline float segmentSDF(vec2 p, vec2 a, vec2 b, float stroke) {
  const float h = segmentParam(p, a, b);
  return lengthv((p - a) - (b - a) * h) - stroke;
}

inline float shapeSDF(vec2 p, const Shape& s) {
  return s.type == SHAPE_CIRCLE ? circleSDF(p, s.a, s.r) : segmentSDF(p, s.a, s.b, s.r);
}

// The point of the shape's core (centre, or point of the segment) closest to p: the closest point
// of the shape lies on the way from p to it, at distance shapeSDF.
inline vec2 corePoint(vec2 p, const Shape& s) {
  if (s.type == SHAPE_CIRCLE) return s.a;
  return s.a + (s.b - s.a) * segmentParam(p, s.a, s.b);
}

// The seed's getClosestPoint: the point of the shape's outline closest to p (p outside).
inline vec2 closestPoint(vec2 p, const Shape& s) {
  const vec2 c = corePoint(p, s);
  const vec2 v = p - c;
  const float len = lengthv(v);
  return len > 0.0f ? c + v * (s.r / len) : c + vec2(s.r, 0.0f);
}

// Signed angle from unit direction n to v, in (-pi, pi].
inline float angleFrom(vec2 n, vec2 v) {
  return dm::atan2(crossv(n, v), dotv(n, v));
}

// Angles (relative to n) of the two tangents from p to the disc (c, r), p outside it.
inline vec2 discSpan(vec2 p, vec2 n, vec2 c, float r) {
  const vec2 v = c - p;
  const float phi = angleFrom(n, v);
  const float half = dm::asin(dm::min(r / lengthv(v), 1.0f));
  return vec2(phi - half, phi + half);
}

// The angles the shape covers as seen from p (outside it), relative to the unit direction n:
// [x, y], less than pi wide. A capsule is the convex hull of its end discs, so its span is the
// hull of theirs, taken around the direction to its own closest point (where every angle of the
// shape lies within pi/2) and then turned to n. Relative to a light's own direction every light
// angle lies in (-pi/2, pi/2); the part of another shape's span that leaves (-pi, pi] wraps to
// beyond -pi/2 or pi/2 there, so spans can be intersected without wrapping.
inline vec2 angularSpan(vec2 p, vec2 n, const Shape& s) {
  if (s.type == SHAPE_CIRCLE) return discSpan(p, n, s.a, s.r);
  const vec2 own = corePoint(p, s) - p;
  const float own_len = lengthv(own);
  const vec2 m = own_len > 0.0f ? own / own_len : n;
  const vec2 ea = discSpan(p, m, s.a, s.r), eb = discSpan(p, m, s.b, s.r);
  const float turn = angleFrom(n, m);
  return vec2(dm::min(ea.x, eb.x) + turn, dm::max(ea.y, eb.y) + turn);
}

// First t >= 0 where the ray p + t * dir (unit dir) enters the disc (c, r), or NO_HIT. Uses
// r^2 - |q|^2 (q the ray's closest approach) rather than b^2 - c, which cancels for far discs.
inline float hitDisc(vec2 p, vec2 dir, vec2 c, float r) {
  const vec2 oc = p - c;
  const float b = dotv(oc, dir);
  const vec2 q = oc - dir * b;
  const float h = r * r - dotv(q, q);
  if (h < 0.0f) return NO_HIT;
  const float t = -b - dm::sqrt(h);
  return t >= 0.0f ? t : NO_HIT;
}

inline float nearerHit(float t0, float t1) {
  if (t0 == NO_HIT) return t1;
  if (t1 == NO_HIT) return t0;
  return dm::min(t0, t1);
}

// First hit of the ray on the shape, p outside it: a capsule is its two end discs and the
// rectangle between them, of which only the long sides can be met first.
inline float hitShape(vec2 p, vec2 dir, const Shape& s) {
  const float ta = hitDisc(p, dir, s.a, s.r);
  if (s.type == SHAPE_CIRCLE) return ta;
  float t = nearerHit(ta, hitDisc(p, dir, s.b, s.r));
  const vec2 ba = s.b - s.a;
  const float len = lengthv(ba);
  if (len > 0.0f) {
    const vec2 axis = ba / len;
    const vec2 nrm = vec2(-axis.y, axis.x);
    const float s0 = dotv(p - s.a, nrm);
    const float dn = dotv(dir, nrm);
    if (dn != 0.0f) {
      // The side facing p: the offset line at +r or -r on p's side of the axis.
      const float side = s0 >= 0.0f ? s.r : -s.r;
      const float ts = (side - s0) / dn;
      const float y = dotv((p + dir * ts) - s.a, axis);
      if (ts >= 0.0f && y >= 0.0f && y <= len) t = nearerHit(t, ts);
    }
  }
  return t;
}

}  // namespace sdfreel::light_beams
