#include "scenes/light_beams/crossings.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace sdfreel::light_beams {
namespace {

using glm::dvec2;

double len(dvec2 v) {
  return std::sqrt(v.x * v.x + v.y * v.y);
}

// A shape's outline is made of full circles and straight sides: a circle is one circle; a
// capsule is its two end circles (of which only the outer halves belong to it) and its two long
// sides. Crossings of these pieces are a superset of the outlines' crossings; onOutline() keeps
// the real ones.
struct Circle {
  dvec2 c;
  double r;
};
struct Side {
  dvec2 p0, p1;
};
struct Outline {
  std::vector<Circle> circles;
  std::vector<Side> sides;
};

Outline outlineOf(const Shape& s) {
  Outline o;
  const dvec2 a(s.a), b(s.b);
  o.circles.push_back({a, s.r});
  if (s.type == SHAPE_CIRCLE) return o;
  o.circles.push_back({b, s.r});
  const double l = len(b - a);
  if (l > 0.0) {
    const dvec2 nrm = dvec2(-(b - a).y, (b - a).x) * (double(s.r) / l);
    o.sides.push_back({a + nrm, b + nrm});
    o.sides.push_back({a - nrm, b - nrm});
  }
  return o;
}

double sdf(dvec2 p, const Shape& s) {
  const dvec2 a(s.a), b(s.b);
  if (s.type == SHAPE_CIRCLE) return len(p - a) - s.r;
  const dvec2 ba = b - a, pa = p - a;
  const double bb = ba.x * ba.x + ba.y * ba.y;
  const double h = bb > 0.0 ? std::clamp((pa.x * ba.x + pa.y * ba.y) / bb, 0.0, 1.0) : 0.0;
  return len(pa - ba * h) - s.r;
}

void crossCircles(const Circle& u, const Circle& v, std::vector<dvec2>& out) {
  const dvec2 d = v.c - u.c;
  const double dist = len(d);
  if (!(dist > 0.0) || dist > u.r + v.r || dist < std::abs(u.r - v.r)) return;
  const double along = (u.r * u.r - v.r * v.r + dist * dist) / (2.0 * dist);
  const double h = std::sqrt(std::max(u.r * u.r - along * along, 0.0));
  const dvec2 e = d / dist, mid = u.c + e * along, perp(-e.y, e.x);
  out.push_back(mid + perp * h);
  out.push_back(mid - perp * h);
}

void crossCircleSide(const Circle& c, const Side& s, std::vector<dvec2>& out) {
  // |p0 + t v - c|^2 = r^2, t in [0, 1].
  const dvec2 v = s.p1 - s.p0, w = s.p0 - c.c;
  const double a = v.x * v.x + v.y * v.y, b = w.x * v.x + w.y * v.y;
  const double disc = b * b - a * (w.x * w.x + w.y * w.y - c.r * c.r);
  if (!(a > 0.0) || disc < 0.0) return;
  const double root = std::sqrt(disc);
  for (const double t : {(-b - root) / a, (-b + root) / a})
    if (t >= 0.0 && t <= 1.0) out.push_back(s.p0 + v * t);
}

void crossSides(const Side& s, const Side& q, std::vector<dvec2>& out) {
  const dvec2 v = s.p1 - s.p0, w = q.p1 - q.p0, d = q.p0 - s.p0;
  const double denom = v.x * w.y - v.y * w.x;
  if (denom == 0.0) return;  // parallel: at most a shared stretch, where the order is a tie
  const double t = (d.x * w.y - d.y * w.x) / denom, k = (d.x * v.y - d.y * v.x) / denom;
  if (t >= 0.0 && t <= 1.0 && k >= 0.0 && k <= 1.0) out.push_back(s.p0 + v * t);
}

// Every crossing of the pieces of the two outlines.
std::vector<dvec2> pieceCrossings(const Outline& p, const Outline& q) {
  std::vector<dvec2> out;
  for (const Circle& c : p.circles) {
    for (const Circle& d : q.circles) crossCircles(c, d, out);
    for (const Side& s : q.sides) crossCircleSide(c, s, out);
  }
  for (const Side& s : p.sides) {
    for (const Circle& d : q.circles) crossCircleSide(d, s, out);
    for (const Side& t : q.sides) crossSides(s, t, out);
  }
  return out;
}

// Size of the pair's coordinates, for tolerances relative to it.
double scaleOf(const Shape& s, const Shape& t) {
  const float m =
      std::max({std::abs(s.a.x), std::abs(s.a.y), std::abs(s.b.x), std::abs(s.b.y), std::abs(t.a.x),
                std::abs(t.a.y), std::abs(t.b.x), std::abs(t.b.y), s.r, t.r});
  return 1.0 + double(m);
}

// The closest points of two shapes' cores (a point, or the segment a-b): two segments that do
// not intersect are closest at an end of one of them.
dvec2 closestOnCore(dvec2 p, const Shape& s) {
  const dvec2 a(s.a), b = s.type == SHAPE_CIRCLE ? dvec2(s.a) : dvec2(s.b);
  const dvec2 ba = b - a;
  const double bb = ba.x * ba.x + ba.y * ba.y;
  const double h =
      bb > 0.0 ? std::clamp(((p - a).x * ba.x + (p - a).y * ba.y) / bb, 0.0, 1.0) : 0.0;
  return a + ba * h;
}

bool coresIntersect(const Shape& s, const Shape& t) {
  if (s.type == SHAPE_CIRCLE || t.type == SHAPE_CIRCLE) return false;
  std::vector<dvec2> out;
  crossSides({dvec2(s.a), dvec2(s.b)}, {dvec2(t.a), dvec2(t.b)}, out);
  return !out.empty();
}

void closestCorePoints(const Shape& s, const Shape& t, dvec2& on_s, dvec2& on_t) {
  double best = 1e300;
  const auto consider = [&](dvec2 x, dvec2 y) {
    if (len(y - x) < best) best = len(y - x), on_s = x, on_t = y;
  };
  for (const dvec2 e : {dvec2(s.a), s.type == SHAPE_CIRCLE ? dvec2(s.a) : dvec2(s.b)})
    consider(e, closestOnCore(e, t));
  for (const dvec2 e : {dvec2(t.a), t.type == SHAPE_CIRCLE ? dvec2(t.a) : dvec2(t.b)})
    consider(closestOnCore(e, s), e);
}

// Whether shape s lies inside t: both end discs of s inside t (t is convex).
bool inside(const Shape& s, const Shape& t) {
  const dvec2 b = s.type == SHAPE_CIRCLE ? dvec2(s.a) : dvec2(s.b);
  return sdf(dvec2(s.a), t) <= -double(s.r) && sdf(b, t) <= -double(s.r);
}

// How s and t (s first) lie; for PAIR_APART, line gets the separating line.
int pairMode(const Shape& s, const Shape& t, glm::vec4& line) {
  if (!coresIntersect(s, t)) {
    dvec2 cs, ct;
    closestCorePoints(s, t, cs, ct);
    const double gap = len(ct - cs) - double(s.r) - double(t.r);
    if (gap > 0.0) {
      const dvec2 n = (ct - cs) / len(ct - cs);
      const dvec2 mid = cs + n * (double(s.r) + 0.5 * gap);
      line = glm::vec4(float(mid.x), float(mid.y), float(n.x), float(n.y));
      return PAIR_APART;
    }
  }
  if (inside(s, t)) return PAIR_FIRST_INSIDE;
  if (inside(t, s)) return PAIR_SECOND_INSIDE;
  return PAIR_CROSSING;
}

}  // namespace

void findCrossings(BeamsUniforms& u) {
  int count = 0;
  for (int i = 0; i < SHAPE_COUNT; ++i) {
    for (int j = 0; j < SHAPE_COUNT; ++j) {
      const int pair = i * SHAPE_COUNT + j;
      u.crossing_first[pair] = count;
      if (!(i < j)) continue;
      const Shape &s = u.shapes[i], &t = u.shapes[j];
      u.pair_mode[pair] = pairMode(s, t, u.pair_line[pair]);
      if (u.pair_mode[pair] != PAIR_CROSSING) continue;
      // A piece's crossing off the outline (inside a capsule) misses it by far more than this;
      // a real one by rounding only. Keeping a near miss merely splits the angles once more.
      const double tol = 1e-9 * scaleOf(s, t);
      std::vector<dvec2> kept;
      for (const dvec2 x : pieceCrossings(outlineOf(s), outlineOf(t))) {
        if (std::abs(sdf(x, s)) > tol || std::abs(sdf(x, t)) > tol) continue;
        bool repeated = false;  // where an end circle meets a side, or ends that are equal
        for (const dvec2 y : kept) repeated = repeated || len(x - y) <= tol;
        if (!repeated && kept.size() < size_t(MAX_PAIR_CROSSINGS) && count < MAX_CROSSINGS) {
          kept.push_back(x);
          u.crossings[count++] = vec2(x);
        }
      }
    }
  }
  u.crossing_first[SHAPE_COUNT * SHAPE_COUNT] = count;
}

}  // namespace sdfreel::light_beams
