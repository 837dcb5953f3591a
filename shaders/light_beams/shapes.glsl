// light_beams: the 2D shapes, the twin of src/scenes/light_beams/shapes.h (same functions, same
// order of operations; every local precise).

const int SHAPE_CIRCLE = 0;
const int SHAPE_SEGMENT = 1;
const float NO_HIT = -1.0;

struct Shape {
  int type;
  vec2 a, b;
  float r;
};

float dotv(vec2 a, vec2 b) { return a.x * b.x + a.y * b.y; }
float crossv(vec2 a, vec2 b) { return a.x * b.y - a.y * b.x; }
float lengthv(vec2 v) { return sqrt(dotv(v, v)); }

float circleSDF(vec2 p, vec2 c, float r) { return lengthv(p - c) - r; }

float segmentParam(vec2 p, vec2 a, vec2 b) {
  precise vec2 ba = b - a;
  precise vec2 pa = p - a;
  precise float bb = dotv(ba, ba);
  return bb > 0.0 ? dm_clamp(dotv(pa, ba) / bb, 0.0, 1.0) : 0.0;
}

float segmentSDF(vec2 p, vec2 a, vec2 b, float stroke) {
  precise float h = segmentParam(p, a, b);
  return lengthv((p - a) - (b - a) * h) - stroke;
}

float shapeSDF(vec2 p, Shape s) {
  return s.type == SHAPE_CIRCLE ? circleSDF(p, s.a, s.r) : segmentSDF(p, s.a, s.b, s.r);
}

vec2 corePoint(vec2 p, Shape s) {
  if (s.type == SHAPE_CIRCLE) return s.a;
  return s.a + (s.b - s.a) * segmentParam(p, s.a, s.b);
}

vec2 closestPoint(vec2 p, Shape s) {
  precise vec2 c = corePoint(p, s);
  precise vec2 v = p - c;
  precise float len = lengthv(v);
  return len > 0.0 ? c + v * (s.r / len) : c + vec2(s.r, 0.0);
}

float angleFrom(vec2 n, vec2 v) { return dm_atan2(crossv(n, v), dotv(n, v)); }

vec2 discSpan(vec2 p, vec2 n, vec2 c, float r) {
  precise vec2 v = c - p;
  precise float phi = angleFrom(n, v);
  precise float half_angle = dm_asin(dm_min(r / lengthv(v), 1.0));
  return vec2(phi - half_angle, phi + half_angle);
}

vec2 angularSpan(vec2 p, vec2 n, Shape s) {
  if (s.type == SHAPE_CIRCLE) return discSpan(p, n, s.a, s.r);
  precise vec2 own = corePoint(p, s) - p;
  precise float own_len = lengthv(own);
  precise vec2 m = own_len > 0.0 ? own / own_len : n;
  precise vec2 ea = discSpan(p, m, s.a, s.r);
  precise vec2 eb = discSpan(p, m, s.b, s.r);
  precise float turn_angle = angleFrom(n, m);
  return vec2(dm_min(ea.x, eb.x) + turn_angle, dm_max(ea.y, eb.y) + turn_angle);
}

float hitDisc(vec2 p, vec2 dir, vec2 c, float r) {
  precise vec2 oc = p - c;
  precise float b = dotv(oc, dir);
  precise vec2 q = oc - dir * b;
  precise float h = r * r - dotv(q, q);
  if (h < 0.0) return NO_HIT;
  precise float t = -b - sqrt(h);
  return t >= 0.0 ? t : NO_HIT;
}

float nearerHit(float t0, float t1) {
  if (t0 == NO_HIT) return t1;
  if (t1 == NO_HIT) return t0;
  return dm_min(t0, t1);
}

float hitShape(vec2 p, vec2 dir, Shape s) {
  precise float ta = hitDisc(p, dir, s.a, s.r);
  if (s.type == SHAPE_CIRCLE) return ta;
  precise float t = nearerHit(ta, hitDisc(p, dir, s.b, s.r));
  precise vec2 ba = s.b - s.a;
  precise float len = lengthv(ba);
  if (len > 0.0) {
    precise vec2 axis = ba / len;
    precise vec2 nrm = vec2(-axis.y, axis.x);
    precise float s0 = dotv(p - s.a, nrm);
    precise float dn = dotv(dir, nrm);
    if (dn != 0.0) {
      precise float side = s0 >= 0.0 ? s.r : -s.r;
      precise float ts = (side - s0) / dn;
      precise float y = dotv((p + dir * ts) - s.a, axis);
      if (ts >= 0.0 && y >= 0.0 && y <= len) t = nearerHit(t, ts);
    }
  }
  return t;
}
