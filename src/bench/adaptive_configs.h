#pragma once
// Adaptive sampling in the bench's sweep (render/adaptive_sampling.h): `final`'s march with
// per-pixel adaptive sampling at several thresholds and maximums, named
// "final:adaptive=<threshold>/<minimum>-<maximum>", next to the fixed "final:spp=N" points.
#include <vector>

#include "bench/sweep.h"

namespace sdfreel::bench {

std::vector<BenchConfig> adaptive_configs();

}  // namespace sdfreel::bench
