#pragma once
// Primary rays as the ray passes of a frame plan hand them to scene code: one ray (scalar path) or
// a packet of eight from one eye (the CPU backend's SIMD unit), and the counters they add up.
#include <cstdint>
#include <glm/glm.hpp>

#include "sdf/lanes.h"

namespace sdfreel {

// Per-sample counters, summed per frame for the bench (SDF evaluations per pixel, step caps).
struct RayStats {
  uint64_t sdf_evals = 0;
  uint64_t steps = 0;
  uint64_t capped = 0;  // rays that hit max_steps
  void add(const RayStats& o) {
    sdf_evals += o.sdf_evals;
    steps += o.steps;
    capped += o.capped;
  }
};

struct Ray {
  glm::vec3 origin;
  glm::vec3 dir;      // unit length
  float pixel_angle;  // angular size of one pixel (radians): hit epsilon grows with t * pixel_angle
};

// Up to LANES primary rays from one eye: the CPU backend's SIMD unit. Lanes >= count are padding
// (copies of the last ray): inactive, never counted in RayStats, their output ignored.
struct RayPacket {
  glm::vec3 origin;
  V3x8 dir;           // unit length
  float pixel_angle;  // as in Ray
  int count = LANES;  // valid lanes, 1..LANES
  M8 valid() const;   // lane < count
  Ray ray(int i) const { return Ray{origin, dir.lane(i), pixel_angle}; }
};

}  // namespace sdfreel
