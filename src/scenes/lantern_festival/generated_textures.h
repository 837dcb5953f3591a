#pragma once
// Generated stand-ins for the seed's image assets: the blue-noise texture that offsets the
// lanterns, and the paper's tiling normal-noise and value-noise maps. All are pure functions of a
// 32-bit seed (no files, no global RNG), so every render with the same timeline seed gets the same
// textures on both backends.
#include <cstdint>
#include <vector>

#include "scenes/common/texture.h"

namespace sdfreel::lantern_festival {

constexpr int BLUE_NOISE_SIZE = 64;
constexpr int PAPER_MAP_SIZE = 256;

// Ulichney's void-and-cluster dither array (1993) on an n x n torus: the rank (0 .. n*n-1) of each
// pixel. Thresholding the ranks at any level gives an evenly spread (blue-noise) point set.
std::vector<int> void_and_cluster_ranks(int n, uint32_t seed);

// `channels` independent void-and-cluster arrays, as (rank + 0.5) / (n*n) in (0, 1).
// Channels of the lantern grid: x, z offset, flicker phase, yaw.
Texture make_blue_noise(int n, int channels, uint32_t seed);

// Tiling paper normal-noise map: tangent-space normals (x around the lantern, y up, z out of the
// paper) of a fibrous height field, stored as n * 0.5 + 0.5 in RGB.
Texture make_paper_normal_map(int n, uint32_t seed);

// Tiling value-noise map in [0, 1] (one channel): blotches that darken the paper's albedo.
Texture make_paper_noise_map(int n, uint32_t seed);

}  // namespace sdfreel::lantern_festival
