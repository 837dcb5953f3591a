#include "draw/map_views.h"

#include <algorithm>
#include <cmath>

namespace sdfreel::draw {

namespace {

constexpr double MARGIN = 1.2;           // the path fills 1/1.2 of the view
constexpr double MIN_HALF_EXTENT = 1.0;  // world units: a still camera gets a 2-unit map
constexpr double FOV_DEG = 40.0;         // narrow: little parallax between path and ground

struct Extent {
  double lo = 1e300, hi = -1e300;
  void add(double v) { lo = std::min(lo, v), hi = std::max(hi, v); }
  double mid() const { return 0.5 * (lo + hi); }
  double half() const { return 0.5 * (hi - lo); }
};

// Fits a camera looking along `forward` (unit) at the points: centred on their extent across the
// view, far enough (or, past `max_distance` from the nearest point, wide enough) to show them.
MapView fit(const std::vector<glm::dvec3>& points, const glm::dvec3& forward, double max_distance,
            int width, const std::string& name) {
  // The basis make_camera_basis gives a camera looking along `forward`.
  CameraPose probe;
  probe.position = glm::dvec3(0.0);
  probe.target = forward;
  const CameraBasis b = make_camera_basis(probe);
  const glm::dvec3 right(b.right), up(b.up);
  Extent across, along, depth;
  for (const glm::dvec3& p : points) {
    across.add(glm::dot(p, right));
    along.add(glm::dot(p, up));
    depth.add(glm::dot(p, forward));
  }
  double half_w = std::max(across.half(), MIN_HALF_EXTENT) * MARGIN;
  double half_h = std::max(along.half(), MIN_HALF_EXTENT) * MARGIN;
  MapView v;
  v.name = name;
  v.width = width;
  const double aspect = std::clamp(half_h / half_w, 0.35, 1.0);
  v.height = std::max(2, int(std::lround(width * aspect)) & ~1);
  half_h = std::max(half_h, half_w * double(v.height) / double(v.width));
  const double tan_half = std::tan(FOV_DEG * M_PI / 360.0);
  double distance = half_h / tan_half;
  double fov = FOV_DEG;
  if (distance > max_distance) {  // under a ceiling: come no nearer, see wider
    distance = std::max(max_distance, 0.05);
    fov = std::min(2.0 * std::atan(half_h / distance) * 180.0 / M_PI, 160.0);
  }
  const glm::dvec3 centre = right * across.mid() + up * along.mid() + forward * depth.lo;
  v.pose.position = centre - forward * distance;
  v.pose.target = centre;
  v.pose.fov_deg = fov;
  v.units_per_pixel = 2.0 * distance * std::tan(fov * M_PI / 360.0) / double(v.height);
  return v;
}

}  // namespace

MapView view_from_above(const std::vector<glm::dvec3>& points, const glm::dvec3& up, double ceiling,
                        int width) {
  const glm::dvec3 u = glm::normalize(up);
  double top = -1e300;
  for (const glm::dvec3& p : points) top = std::max(top, glm::dot(p, u));
  return fit(points, -u, ceiling - top, width, "from above");
}

MapView view_from_side(const std::vector<glm::dvec3>& points, int width) {
  Extent x, z;
  for (const glm::dvec3& p : points) x.add(p.x), z.add(p.z);
  // Across the longer extent: a path along z is seen looking along -x, from +x.
  const glm::dvec3 forward = z.half() >= x.half() ? glm::dvec3(-1, 0, 0) : glm::dvec3(0, 0, 1);
  return fit(points, forward, 1e300, width, "from the side");
}

glm::dvec2 project(const MapView& view, const glm::dvec3& p, bool* visible) {
  const CameraBasis b = make_camera_basis(view.pose);
  const glm::dvec3 v = p - view.pose.position;
  const double z = glm::dot(v, glm::dvec3(b.forward));
  if (visible) *visible = z > 1e-9;
  const double t = std::tan(view.pose.fov_deg * M_PI / 360.0) * std::max(z, 1e-9);
  const double sx = glm::dot(v, glm::dvec3(b.right)) / t;
  const double sy = glm::dot(v, glm::dvec3(b.up)) / t;
  const double w = view.width, h = view.height;
  return {0.5 * (sx * h + w), 0.5 * (h - sy * h)};
}

}  // namespace sdfreel::draw
