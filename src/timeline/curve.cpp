#include "timeline/curve.h"

#include <algorithm>
#include <cmath>

namespace sdfreel {

std::optional<Interp> parse_interp(const std::string& name) {
  if (name == "step") return Interp::Step;
  if (name == "linear") return Interp::Linear;
  if (name == "smooth") return Interp::Smooth;
  if (name == "catmull-rom") return Interp::CatmullRom;
  return std::nullopt;
}

const char* interp_name(Interp interp) {
  static const char* names[] = {"step", "linear", "smooth", "catmull-rom"};
  return names[int(interp)];
}

namespace {

using Vec = std::vector<double>;

Vec lerp(const Vec& a, const Vec& b, double s) {
  Vec out(a.size());
  for (size_t i = 0; i < a.size(); ++i) out[i] = a[i] + (b[i] - a[i]) * s;
  return out;
}

// Euclidean distance, scaled so that huge coordinates do not overflow when squared.
double distance(const Vec& a, const Vec& b) {
  double scale = 0.0;
  for (size_t i = 0; i < a.size(); ++i) scale = std::max(scale, std::fabs(b[i] - a[i]));
  if (scale == 0.0 || !std::isfinite(scale)) return scale;
  double sum = 0.0;
  for (size_t i = 0; i < a.size(); ++i) {
    double d = (b[i] - a[i]) / scale;
    sum += d * d;
  }
  return std::sqrt(sum) * scale;
}

// Point between a (at knot ta) and b (at knot tb) for knot value x; Barry-Goldman pyramid step.
Vec blend(const Vec& a, const Vec& b, double ta, double tb, double x) {
  Vec out(a.size());
  const double wa = (tb - x) / (tb - ta), wb = (x - ta) / (tb - ta);
  for (size_t i = 0; i < a.size(); ++i) out[i] = a[i] * wa + b[i] * wb;
  return out;
}

// Centripetal Catmull-Rom (alpha = 0.5) between p1 and p2 at fraction s in [0, 1], with
// neighbours p0 and p3.
Vec catmull_rom(const Vec& p0, const Vec& p1, const Vec& p2, const Vec& p3, double s) {
  // Knot intervals are distance^alpha; sqrt is exact-rounded, so this stays deterministic.
  double d0 = std::sqrt(distance(p0, p1));
  const double d1 = std::sqrt(distance(p1, p2));
  double d2 = std::sqrt(distance(p2, p3));
  if (d1 == 0.0) return p1;  // the segment is a single point
  // A neighbour that coincides with its end point makes a zero knot interval (0/0 below). Its
  // blend term is that same point whatever the interval, so any positive interval is exact.
  // Guarded by tests/hard_cases/sdf_morph/repeated_camera_keys.
  if (d0 <= 1e-12 * d1) d0 = d1;
  if (d2 <= 1e-12 * d1) d2 = d1;
  const double t0 = 0.0, t1 = d0, t2 = d0 + d1, t3 = d0 + d1 + d2;
  const double x = t1 + s * d1;
  Vec a1 = blend(p0, p1, t0, t1, x);
  Vec a2 = blend(p1, p2, t1, t2, x);
  Vec a3 = blend(p2, p3, t2, t3, x);
  Vec b1 = blend(a1, a2, t0, t2, x);
  Vec b2 = blend(a2, a3, t1, t3, x);
  return blend(b1, b2, t1, t2, x);
}

// The key mirrored through `end` (2 * end - other): a virtual neighbour beyond the first or last
// key that keeps the end tangent pointing along the end segment.
Vec mirror(const Vec& end, const Vec& other) {
  Vec out(end.size());
  for (size_t i = 0; i < end.size(); ++i) out[i] = end[i] + (end[i] - other[i]);
  return out;
}

}  // namespace

std::vector<double> Curve::sample(double at) const {
  if (t.empty()) return {};
  if (!(at > t.front())) return values.front();  // also catches NaN: hold the first value
  if (at >= t.back()) return values.back();
  // Segment k: t[k] <= at < t[k + 1].
  const size_t k = size_t(std::upper_bound(t.begin(), t.end(), at) - t.begin()) - 1;
  if (at == t[k]) return values[k];
  const double s = (at - t[k]) / (t[k + 1] - t[k]);
  const Vec& v1 = values[k];
  const Vec& v2 = values[k + 1];
  switch (interp) {
    case Interp::Step:
      return v1;
    case Interp::Linear:
      return lerp(v1, v2, s);
    case Interp::Smooth:
      return lerp(v1, v2, s * s * (3.0 - 2.0 * s));
    case Interp::CatmullRom: {
      Vec v0 = k > 0 ? values[k - 1] : mirror(v1, v2);
      Vec v3 = k + 2 < values.size() ? values[k + 2] : mirror(v2, v1);
      return catmull_rom(v0, v1, v2, v3, s);
    }
  }
  return v1;
}

}  // namespace sdfreel
