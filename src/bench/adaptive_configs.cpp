#include "bench/adaptive_configs.h"

#include <cstdio>
#include <cstdlib>

namespace sdfreel::bench {

namespace {

const int MINIMUM_VALUES[] = {1, 2};
const int MAXIMUM_VALUES[] = {16, 32};
const float THRESHOLD_VALUES[] = {0.006f, 0.01f, 0.015f, 0.02f, 0.025f, 0.03f};

const char PREFIX[] = "final:adaptive=";

BenchConfig adaptive_config(float threshold, int minimum, int maximum) {
  BenchConfig c{"final", Quality::Final, march_settings(Quality::Final), 1, false};
  c.adaptive = AdaptiveSampling{true, minimum, maximum, threshold};
  char name[64];
  std::snprintf(name, sizeof name, "%s%g/%d-%d", PREFIX, double(threshold), minimum, maximum);
  c.name = name;
  return c;
}

}  // namespace

std::vector<BenchConfig> adaptive_configs() {
  std::vector<BenchConfig> out;
  for (int minimum : MINIMUM_VALUES)
    for (int maximum : MAXIMUM_VALUES)
      for (float threshold : THRESHOLD_VALUES)
        out.push_back(adaptive_config(threshold, minimum, maximum));
  return out;
}

std::optional<BenchConfig> adaptive_config_named(const std::string& name) {
  const std::string prefix = PREFIX;
  if (name.compare(0, prefix.size(), prefix) != 0) return std::nullopt;
  const char* s = name.c_str() + prefix.size();
  char* end = nullptr;
  const double threshold = std::strtod(s, &end);
  if (end == s || *end != '/') return std::nullopt;
  s = end + 1;
  const long minimum = std::strtol(s, &end, 10);
  if (end == s || *end != '-') return std::nullopt;
  s = end + 1;
  const long maximum = std::strtol(s, &end, 10);
  if (end == s || *end != '\0') return std::nullopt;
  if (!(threshold >= 0.0 && threshold <= 1.0) || minimum < 1 || maximum < minimum || maximum > 1024)
    return std::nullopt;
  return adaptive_config(float(threshold), int(minimum), int(maximum));
}

}  // namespace sdfreel::bench
