// CameraPath::sample: keyframed camera poses, optionally re-timed for constant speed.
#include <algorithm>

#include "timeline/timeline.h"

namespace sdfreel {
namespace {

// Arc-length table resolution: segments per key interval. Fixed, so sampling is deterministic.
constexpr int kArcSegments = 1024;

struct PathCurves {
  Curve position, target, fov, roll;
};

PathCurves make_curves(const CameraPath& path) {
  PathCurves c;
  for (Curve* curve : {&c.position, &c.target, &c.fov, &c.roll}) curve->interp = path.interp;
  for (const CameraKey& key : path.keys) {
    const CameraPose& p = key.pose;
    for (Curve* curve : {&c.position, &c.target, &c.fov, &c.roll}) curve->t.push_back(key.t);
    c.position.values.push_back({p.position.x, p.position.y, p.position.z});
    c.target.values.push_back({p.target.x, p.target.y, p.target.z});
    c.fov.values.push_back({p.fov_deg});
    c.roll.values.push_back({p.roll_deg});
  }
  return c;
}

glm::dvec3 to_dvec3(const std::vector<double>& v) {
  return {v[0], v[1], v[2]};
}

CameraPose pose_at(const PathCurves& c, double t) {
  CameraPose pose;
  pose.position = to_dvec3(c.position.sample(t));
  pose.target = to_dvec3(c.target.sample(t));
  pose.fov_deg = c.fov.sample(t)[0];
  pose.roll_deg = c.roll.sample(t)[0];
  return pose;
}

// The key time at which the position curve has covered `fraction` (0..1) of its total length,
// found in a dense table of chord lengths.
double arc_length_time(const Curve& position, double fraction) {
  const std::vector<double>& keys = position.t;
  std::vector<double> times{keys.front()}, lengths{0.0};
  glm::dvec3 prev = to_dvec3(position.values.front());
  for (size_t k = 0; k + 1 < keys.size(); ++k) {
    for (int j = 1; j <= kArcSegments; ++j) {
      double t = j == kArcSegments ? keys[k + 1]
                                   : keys[k] + (keys[k + 1] - keys[k]) * (double(j) / kArcSegments);
      glm::dvec3 p = to_dvec3(position.sample(t));
      times.push_back(t);
      lengths.push_back(lengths.back() + glm::distance(prev, p));
      prev = p;
    }
  }
  const double total = lengths.back();
  if (!(total > 0.0)) return keys.front() + fraction * (keys.back() - keys.front());
  const double goal = fraction * total;
  size_t i = size_t(std::lower_bound(lengths.begin(), lengths.end(), goal) - lengths.begin());
  if (i == 0) return times.front();
  if (i == lengths.size()) return times.back();
  const double span = lengths[i] - lengths[i - 1];
  if (!(span > 0.0)) return times[i];
  return times[i - 1] + (times[i] - times[i - 1]) * ((goal - lengths[i - 1]) / span);
}

}  // namespace

CameraPose CameraPath::sample(double t, const CameraPose& fallback) const {
  if (keys.empty()) return fallback;
  PathCurves curves = make_curves(*this);
  const double first = keys.front().t, last = keys.back().t;
  if (constant_speed && keys.size() > 1 && t > first && t < last) {
    // Position, target, fov and roll all follow the re-timed parameter, so the camera keeps
    // looking where the keys say it looks at each point of the path.
    t = arc_length_time(curves.position, (t - first) / (last - first));
  }
  return pose_at(curves, t);
}

}  // namespace sdfreel
