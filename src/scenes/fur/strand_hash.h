#pragma once
// The random value of one strand: a 2D integer hash of its UV cell, bit for bit the same as
// shaders/fur/strand_hash.glsl. pcg2d (Jarzynski & Olano, "Hash Functions for GPU Rendering",
// 2020) is a bijection of uint32 pairs, so no two cells share a seed (the usual x + 100 * y seed
// collides as soon as density passes 100). Every constant fits in 32 bits: wider hex literals wrap
// silently in C++ and are refused by GLSL.
#include <cstdint>
#include <glm/glm.hpp>

namespace sdfreel::fur {

constexpr uint32_t PCG_MULTIPLIER = 1664525u;
constexpr uint32_t PCG_INCREMENT = 1013904223u;

inline glm::uvec2 pcg2d(glm::uvec2 v) {
  v = v * PCG_MULTIPLIER + PCG_INCREMENT;
  v.x += v.y * PCG_MULTIPLIER;
  v.y += v.x * PCG_MULTIPLIER;
  v ^= v >> 16u;
  v.x += v.y * PCG_MULTIPLIER;
  v.y += v.x * PCG_MULTIPLIER;
  v ^= v >> 16u;
  return v;
}

// In [0, 1): the top 24 bits of the hash, exact in a float on both backends.
inline float strand_random(int cell_x, int cell_y) {
  const glm::uvec2 h = pcg2d(glm::uvec2(uint32_t(cell_x), uint32_t(cell_y)));
  return float(h.x >> 8u) * (1.0f / 16777216.0f);
}

}  // namespace sdfreel::fur
