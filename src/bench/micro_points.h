#pragma once
// The points at which `sdfreel bench --micro` evaluates a scene's distance functions: where a
// march from the frame's camera would ask, without depending on any scene's march.
#include <cstdint>
#include <vector>

#include "render/camera.h"

namespace sdfreel::bench {

// Structure of arrays, as DistanceFunction takes them; size() is a multiple of LANES.
struct SamplePoints {
  std::vector<float> x, y, z;
  int size() const { return int(x.size()); }
};

// Defaults of the micro-benchmark: a 64x36 view (2304 points) and distances up to 30 units, the
// same for every scene so that rates compare across scenes.
constexpr int MICRO_VIEW_WIDTH = 64, MICRO_VIEW_HEIGHT = 36;
constexpr float MICRO_MAX_DISTANCE = 30.0f;
constexpr uint64_t MICRO_POINT_SEED = 1;

// One point per pixel centre of a width x height view: origin + t * primary ray direction, with t
// uniform in [0, max_t) from a counter-based hash of (seed, pixel), so the set is the same on
// every machine and standard library. width * height must be a multiple of LANES.
SamplePoints camera_sample_points(const CameraBasis& camera, int width, int height, float max_t,
                                  uint64_t seed);

}  // namespace sdfreel::bench
