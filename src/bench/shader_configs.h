#pragma once
// What `sdfreel bench` measures for a user's shader (docs/shaders.md): the only setting that
// trades speed for error is the Image pass's samples a pixel, so the configurations are sample
// counts, and the reference is the same shader at many samples, on the GL backend (a shader has
// no CPU twin).
#include <vector>

#include "bench/sweep.h"

namespace sdfreel::bench {

constexpr int SHADER_REFERENCE_SAMPLES = 64;

// spp=1, 2, 4, 8 and 16.
std::vector<BenchConfig> shader_sample_configs();
// SHADER_REFERENCE_SAMPLES samples a pixel.
BenchConfig shader_reference_config();

}  // namespace sdfreel::bench
