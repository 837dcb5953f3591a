#pragma once
// What the bench measures: the named presets (naive, draft, final), the reference they are
// measured against, and a sweep over the march parameters from which the presets are chosen.
#include <string>
#include <vector>

#include "render/adaptive_sampling.h"
#include "render/quality.h"

namespace sdfreel::bench {

struct BenchConfig {
  std::string name;
  Quality quality = Quality::Final;  // what the scene sees as ctx.quality
  MarchSettings march{};
  int samples = 1;
  bool named_preset = false;
  AdaptiveSampling adaptive{};  // enabled: instead of `samples`
};

// naive, draft, final: quality.cpp's numbers at the samples each preset was chosen for.
std::vector<BenchConfig> preset_configs();
// The same for frames of width x height: on a small frame `final` is adaptive 4..28 (quality.h),
// what `adaptive = true` does in a `final` timeline there.
std::vector<BenchConfig> preset_configs(int width, int height);
// One parameter at a time around `draft` and around `final`: hit epsilon, relaxation, step budget
// (max, shadow and reflection steps scaled together), normal epsilon, far limit and samples.
std::vector<BenchConfig> sweep_configs();
// The reference preset with many samples.
BenchConfig reference_config();

// Same settings (and samples): a sweep point that repeats a preset is measured once.
bool same_settings(const BenchConfig& a, const BenchConfig& b);
// A stable text of every setting, for cache keys.
std::string settings_text(const BenchConfig& c);

}  // namespace sdfreel::bench
