#pragma once
// Before any timing: a distance function's eight-lane path must give the scalar path's bits at
// every sample point, or the rates would compare two different functions.
#include <optional>
#include <string>

#include "bench/micro_points.h"
#include "scenes/scene.h"

namespace sdfreel::bench {

struct LaneMismatch {
  int index = 0;  // first point whose bits differ
  float x = 0, y = 0, z = 0;
  float scalar = 0, lanes = 0;
};

// The first point where `lanes` and `scalar` give different bits (NaNs compared bit for bit too).
std::optional<LaneMismatch> first_lane_mismatch(const DistanceFunction& fn,
                                                const SamplePoints& points);

// "SCENE/FUNCTION: lanes differ from scalar at point I (x, y, z): scalar S (0xBITS), lanes L
// (0xBITS)".
std::string describe(const std::string& scene, const std::string& function, const LaneMismatch& m);

}  // namespace sdfreel::bench
