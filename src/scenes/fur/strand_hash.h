#pragma once
// The random value of one strand: a 2D integer hash of its UV cell, bit for bit the same as
// shaders/fur/strand_hash.glsl. pcg2d (Jarzynski & Olano, "Hash Functions for GPU Rendering",
// 2020) is a bijection of uint32 pairs, so no two cells share a seed (the usual x + 100 * y seed
// collides as soon as density passes 100). Every constant fits in 32 bits: wider hex literals wrap
// silently in C++ and are refused by GLSL.
#include <cstdint>
#include <glm/glm.hpp>

#include "sdf/lanes_exp_log.h"

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

// Eight cells at once: lane k is strand_random(cell_x[k], cell_y[k]), the same integer steps.
inline F8 strand_random(M8 cell_x, M8 cell_y) {
  U8 x = reinterpret_cast<U8>(cell_x) * PCG_MULTIPLIER + PCG_INCREMENT;
  U8 y = reinterpret_cast<U8>(cell_y) * PCG_MULTIPLIER + PCG_INCREMENT;
  x += y * PCG_MULTIPLIER;
  y += x * PCG_MULTIPLIER;
  x ^= x >> 16u;
  y ^= y >> 16u;
  x += y * PCG_MULTIPLIER;
  x ^= x >> 16u;  // y's last steps do not reach the result
  return dm::to_float(reinterpret_cast<M8>(x >> 8u)) * (1.0f / 16777216.0f);
}

}  // namespace sdfreel::fur
