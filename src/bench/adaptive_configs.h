#pragma once
// Adaptive sampling in the bench's sweep (render/adaptive_sampling.h): `final`'s march with
// per-pixel adaptive sampling at several thresholds and maximums, named
// "final:adaptive=<threshold>/<minimum>-<maximum>", next to the fixed "final:spp=N" points.
#include <optional>
#include <string>
#include <vector>

#include "bench/sweep.h"

namespace sdfreel::bench {

std::vector<BenchConfig> adaptive_configs();
// The adaptive point a name of that form describes, sweep point or not (`--only` may name any,
// e.g. "final:adaptive=0.004/2-64"); nullopt when `name` is not of that form or out of range
// (threshold 0..1, 1 <= minimum <= maximum <= 1024).
std::optional<BenchConfig> adaptive_config_named(const std::string& name);

}  // namespace sdfreel::bench
