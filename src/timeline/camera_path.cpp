// CameraPath::sample: keyframed camera poses, optionally re-timed for constant speed.
#include <algorithm>

#include "timeline/timeline.h"

namespace sdfreel {
namespace {

// Arc-length table resolution: segments per key interval, 1024 up to 1024 intervals, then fewer
// (at least 8) so the table stays near 2^20 entries (16 MiB) however many keys there are. A
// function of the key count only, so sampling is deterministic.
constexpr int kArcSegments = 1024;
constexpr size_t kArcTableEntries = size_t(1) << 20;
constexpr int kMinArcSegments = 8;

int arc_segments(size_t intervals) {
  if (intervals == 0) return kArcSegments;
  const size_t fit = kArcTableEntries / intervals;
  return int(std::clamp<size_t>(fit, kMinArcSegments, kArcSegments));
}

struct PathCurves {
  Curve position, target, fov, roll;
};

// Cumulative chord length of the position curve against key time.
struct ArcTable {
  std::vector<double> times, lengths;
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

ArcTable make_arc_table(const Curve& position) {
  const std::vector<double>& keys = position.t;
  const int segments = arc_segments(keys.size() - 1);
  ArcTable a;
  a.times.reserve((keys.size() - 1) * size_t(segments) + 1);
  a.lengths.reserve(a.times.capacity());
  a.times.push_back(keys.front());
  a.lengths.push_back(0.0);
  glm::dvec3 prev = to_dvec3(position.values.front());
  for (size_t k = 0; k + 1 < keys.size(); ++k) {
    for (int j = 1; j <= segments; ++j) {
      double t =
          j == segments ? keys[k + 1] : keys[k] + (keys[k + 1] - keys[k]) * (double(j) / segments);
      glm::dvec3 p = to_dvec3(position.sample(t));
      a.times.push_back(t);
      a.lengths.push_back(a.lengths.back() + glm::distance(prev, p));
      prev = p;
    }
  }
  return a;
}

// The key time at which the position curve has covered `fraction` (0..1) of its total length,
// found in the table by binary search.
double arc_length_time(const ArcTable& table, const std::vector<double>& keys, double fraction) {
  const std::vector<double>& times = table.times;
  const std::vector<double>& lengths = table.lengths;
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

struct CameraPathTables {
  PathCurves curves;
  ArcTable arc;  // empty unless constant_speed with two keys or more
};

namespace {

std::shared_ptr<const CameraPathTables> make_tables(const CameraPath& path) {
  auto tables = std::make_shared<CameraPathTables>();
  tables->curves = make_curves(path);
  if (path.constant_speed && path.keys.size() > 1)
    tables->arc = make_arc_table(tables->curves.position);
  return tables;
}

}  // namespace

void CameraPath::prepare() {
  tables_ = keys.empty() ? nullptr : make_tables(*this);
}

CameraPose CameraPath::sample(double t, const CameraPose& fallback) const {
  if (keys.empty()) return fallback;
  const std::shared_ptr<const CameraPathTables> tables = tables_ ? tables_ : make_tables(*this);
  const double first = keys.front().t, last = keys.back().t;
  if (constant_speed && keys.size() > 1 && t > first && t < last) {
    // Position, target, fov and roll all follow the re-timed parameter, so the camera keeps
    // looking where the keys say it looks at each point of the path.
    t = arc_length_time(tables->arc, tables->curves.position.t, (t - first) / (last - first));
  }
  return pose_at(tables->curves, t);
}

}  // namespace sdfreel
