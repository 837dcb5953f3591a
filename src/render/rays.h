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
  // SDF evaluations of each lane of the packet being traced, for the sdf_evals compositing pass:
  // the runner zeroes them before a packet and reads them after (never summed by add()). Lane
  // code counts through count_evals(); scalar code adds to sdf_evals only, and the runners of
  // scalar rays attribute the difference to the ray's lane.
  M8 lane_evals = splat_mask(false);
  // `per_lane` evaluations for each lane in `active`.
  void count_evals(M8 active, int32_t per_lane = 1) {
    sdf_evals += count_lanes(active) * uint64_t(per_lane);
    lane_evals -= active * per_lane;  // active lanes are -1
  }
  void add(const RayStats& o) {
    sdf_evals += o.sdf_evals;
    steps += o.steps;
    capped += o.capped;
  }
};

// While it lives, what scalar code counts goes to lane `lane` too: packet code that shades some of
// its lanes one at a time.
class LaneEvalScope {
 public:
  LaneEvalScope(RayStats& stats, int lane) : stats_(stats), lane_(lane), before_(stats.sdf_evals) {}
  ~LaneEvalScope() { stats_.lane_evals[lane_] += int32_t(stats_.sdf_evals - before_); }
  LaneEvalScope(const LaneEvalScope&) = delete;
  LaneEvalScope& operator=(const LaneEvalScope&) = delete;

 private:
  RayStats& stats_;
  int lane_;
  uint64_t before_;
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
