#include "bench/adaptive_configs.h"

#include <cstdio>

namespace sdfreel::bench {

namespace {

const int MINIMUM_VALUES[] = {1, 2};
const int MAXIMUM_VALUES[] = {16, 32};
const float THRESHOLD_VALUES[] = {0.006f, 0.01f, 0.015f, 0.02f, 0.025f, 0.03f};

}  // namespace

std::vector<BenchConfig> adaptive_configs() {
  std::vector<BenchConfig> out;
  const BenchConfig base{"final", Quality::Final, march_settings(Quality::Final), 1, false};
  for (int minimum : MINIMUM_VALUES)
    for (int maximum : MAXIMUM_VALUES)
      for (float threshold : THRESHOLD_VALUES) {
        BenchConfig c = base;
        c.adaptive = AdaptiveSampling{true, minimum, maximum, threshold};
        char name[64];
        std::snprintf(name, sizeof name, "final:adaptive=%g/%d-%d", double(threshold), minimum,
                      maximum);
        c.name = name;
        out.push_back(c);
      }
  return out;
}

}  // namespace sdfreel::bench
