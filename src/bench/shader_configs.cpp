#include "bench/shader_configs.h"

#include <string>

namespace sdfreel::bench {

std::vector<BenchConfig> shader_sample_configs() {
  std::vector<BenchConfig> out;
  for (int n : {1, 2, 4, 8, 16}) {
    BenchConfig c;
    c.name = "spp=" + std::to_string(n);
    c.samples = n;
    out.push_back(c);
  }
  return out;
}

BenchConfig shader_reference_config() {
  BenchConfig c;
  c.name = "reference";
  c.quality = Quality::Reference;
  c.samples = SHADER_REFERENCE_SAMPLES;
  return c;
}

}  // namespace sdfreel::bench
