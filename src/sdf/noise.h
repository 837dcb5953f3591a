#pragma once
// Deterministic procedural noise: integer hashes (exact uint32 arithmetic, identical in GLSL with
// uint), value noise, fbm and Worley (cellular) noise in 2D and 3D. A `seed` selects independent
// patterns. Lattice coordinates are clamped to +-2^30 so that float -> int never overflows.
#include <cstdint>
#include <glm/glm.hpp>

#include "sdf/det_math.h"

namespace sdfreel {

// PCG-based hash (Jarzynski & Olano 2020, "Hash Functions for GPU Rendering").
inline uint32_t pcg_hash(uint32_t v) {
  const uint32_t state = v * 747796405u + 2891336453u;
  const uint32_t word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
  return (word >> 22u) ^ word;
}

// Three hashes at once (same paper); good for 3D cell data.
inline glm::uvec3 pcg3d(glm::uvec3 v) {
  v = v * 1664525u + 1013904223u;
  v.x += v.y * v.z;
  v.y += v.z * v.x;
  v.z += v.x * v.y;
  v ^= v >> 16u;
  v.x += v.y * v.z;
  v.y += v.z * v.x;
  v.z += v.x * v.y;
  return v;
}

// Hash of integer lattice points, chained so every coordinate affects every bit.
inline uint32_t hash2i(int32_t x, int32_t y, uint32_t seed) {
  return pcg_hash(uint32_t(x) ^ pcg_hash(uint32_t(y) ^ pcg_hash(seed)));
}
inline uint32_t hash3i(int32_t x, int32_t y, int32_t z, uint32_t seed) {
  return pcg_hash(uint32_t(x) ^ pcg_hash(uint32_t(y) ^ pcg_hash(uint32_t(z) ^ pcg_hash(seed))));
}

constexpr float INV_2_POW_24 = 1.0f / 16777216.0f;
// Top 24 bits as a float in [0, 1), exactly.
inline float hash_to_unit(uint32_t h) {
  return float(h >> 8u) * INV_2_POW_24;
}

constexpr float NOISE_CELL_LIMIT = 1073741824.0f;  // 2^30
inline int32_t noise_cell(float floored) {
  return int32_t(dm::clamp(floored, -NOISE_CELL_LIMIT, NOISE_CELL_LIMIT));
}

// Cubic fade 3t^2 - 2t^3 (C1 at cell borders).
inline float noise_fade(float t) {
  return t * t * (3.0f - 2.0f * t);
}

// Value noise in [0, 1).
inline float value_noise(const glm::vec2& p, uint32_t seed) {
  const float fx = dm::floor(p.x), fy = dm::floor(p.y);
  const float ux = noise_fade(p.x - fx), uy = noise_fade(p.y - fy);
  const int32_t ix = noise_cell(fx), iy = noise_cell(fy);
  const float a = hash_to_unit(hash2i(ix, iy, seed));
  const float b = hash_to_unit(hash2i(ix + 1, iy, seed));
  const float c = hash_to_unit(hash2i(ix, iy + 1, seed));
  const float d = hash_to_unit(hash2i(ix + 1, iy + 1, seed));
  return dm::mix(dm::mix(a, b, ux), dm::mix(c, d, ux), uy);
}

inline float value_noise(const glm::vec3& p, uint32_t seed) {
  const float fx = dm::floor(p.x), fy = dm::floor(p.y), fz = dm::floor(p.z);
  const float ux = noise_fade(p.x - fx), uy = noise_fade(p.y - fy), uz = noise_fade(p.z - fz);
  const int32_t ix = noise_cell(fx), iy = noise_cell(fy), iz = noise_cell(fz);
  float layer[2];
  for (int k = 0; k < 2; ++k) {
    const float a = hash_to_unit(hash3i(ix, iy, iz + k, seed));
    const float b = hash_to_unit(hash3i(ix + 1, iy, iz + k, seed));
    const float c = hash_to_unit(hash3i(ix, iy + 1, iz + k, seed));
    const float d = hash_to_unit(hash3i(ix + 1, iy + 1, iz + k, seed));
    layer[k] = dm::mix(dm::mix(a, b, ux), dm::mix(c, d, ux), uy);
  }
  return dm::mix(layer[0], layer[1], uz);
}

// Fractal sum of `octaves` value-noise layers (frequency x2, amplitude x0.5, shifted so lattice
// points do not line up), normalised to [0, 1). octaves < 1 gives 0.
constexpr float FBM_LACUNARITY = 2.0f;
constexpr float FBM_GAIN = 0.5f;
constexpr float FBM_SHIFT = 17.31f;

inline float fbm(glm::vec2 p, int octaves, uint32_t seed) {
  float sum = 0.0f, amp = 0.5f, norm = 0.0f;
  for (int i = 0; i < octaves; ++i) {
    sum += amp * value_noise(p, seed + uint32_t(i));
    norm += amp;
    p = p * FBM_LACUNARITY + glm::vec2(FBM_SHIFT);
    amp *= FBM_GAIN;
  }
  return norm > 0.0f ? sum / norm : 0.0f;
}

inline float fbm(glm::vec3 p, int octaves, uint32_t seed) {
  float sum = 0.0f, amp = 0.5f, norm = 0.0f;
  for (int i = 0; i < octaves; ++i) {
    sum += amp * value_noise(p, seed + uint32_t(i));
    norm += amp;
    p = p * FBM_LACUNARITY + glm::vec3(FBM_SHIFT);
    amp *= FBM_GAIN;
  }
  return norm > 0.0f ? sum / norm : 0.0f;
}

// Worley noise: distances to the nearest and second-nearest feature points (one random point per
// unit cell), as (F1, F2).
inline glm::vec2 worley(const glm::vec2& p, uint32_t seed) {
  const float fx = dm::floor(p.x), fy = dm::floor(p.y);
  const glm::vec2 f(p.x - fx, p.y - fy);
  const int32_t ix = noise_cell(fx), iy = noise_cell(fy);
  float f1 = 1e10f, f2 = 1e10f;  // squared distances
  for (int j = -1; j <= 1; ++j)
    for (int i = -1; i <= 1; ++i) {
      const uint32_t h = hash2i(ix + i, iy + j, seed);
      const glm::vec2 feature(float(i) + hash_to_unit(h), float(j) + hash_to_unit(pcg_hash(h)));
      const float d2 = glm::dot(feature - f, feature - f);
      if (d2 < f1) {
        f2 = f1;
        f1 = d2;
      } else if (d2 < f2) {
        f2 = d2;
      }
    }
  return glm::vec2(dm::sqrt(f1), dm::sqrt(f2));
}

inline glm::vec2 worley(const glm::vec3& p, uint32_t seed) {
  const float fx = dm::floor(p.x), fy = dm::floor(p.y), fz = dm::floor(p.z);
  const glm::vec3 f(p.x - fx, p.y - fy, p.z - fz);
  const int32_t ix = noise_cell(fx), iy = noise_cell(fy), iz = noise_cell(fz);
  float f1 = 1e10f, f2 = 1e10f;
  for (int k = -1; k <= 1; ++k)
    for (int j = -1; j <= 1; ++j)
      for (int i = -1; i <= 1; ++i) {
        const uint32_t h = hash3i(ix + i, iy + j, iz + k, seed);
        const uint32_t h2 = pcg_hash(h);
        const glm::vec3 feature(float(i) + hash_to_unit(h), float(j) + hash_to_unit(h2),
                                float(k) + hash_to_unit(pcg_hash(h2)));
        const float d2 = glm::dot(feature - f, feature - f);
        if (d2 < f1) {
          f2 = f1;
          f1 = d2;
        } else if (d2 < f2) {
          f2 = d2;
        }
      }
  return glm::vec2(dm::sqrt(f1), dm::sqrt(f2));
}

}  // namespace sdfreel
