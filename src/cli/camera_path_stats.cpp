#include "cli/camera_path_stats.h"

#include <algorithm>
#include <glm/geometric.hpp>

namespace sdfreel {

CameraPathStats camera_path_stats(const Timeline& tl, const CameraPose& fallback) {
  CameraPathStats s;
  const auto& keys = tl.camera.keys;
  if (keys.size() < 2) return s;
  const double t0 = keys.front().t, t1 = keys.back().t;
  // Four steps a frame, at most 100000 in all (a long timeline's top speed stays close enough).
  const int steps = int(std::clamp((t1 - t0) * tl.fps.value() * 4.0, 1.0, 100000.0));
  const double dt = (t1 - t0) / steps;
  glm::dvec3 last = tl.camera.sample(t0, fallback).position;
  for (int i = 1; i <= steps; ++i) {
    const double t = t0 + dt * i;
    const glm::dvec3 p = tl.camera.sample(t, fallback).position;
    const double d = glm::length(p - last);
    s.length += d;
    if (d / dt > s.top_speed) s.top_speed = d / dt, s.top_speed_at = t - dt / 2;
    last = p;
  }
  return s;
}

}  // namespace sdfreel
