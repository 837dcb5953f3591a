// Deterministic procedural noise: the twin of src/sdf/noise.h. Hashes are exact uint arithmetic
// (wrapping like C++ uint32_t), so both backends see the same random numbers.
#include "common/det_math.glsl"
#include "common/sdf.glsl"

uint pcg_hash(uint v) {
  uint state = v * 747796405u + 2891336453u;
  uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
  return (word >> 22u) ^ word;
}

uvec3 pcg3d(uvec3 v) {
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

uint hash2i(int x, int y, uint seed) {
  return pcg_hash(uint(x) ^ pcg_hash(uint(y) ^ pcg_hash(seed)));
}
uint hash3i(int x, int y, int z, uint seed) {
  return pcg_hash(uint(x) ^ pcg_hash(uint(y) ^ pcg_hash(uint(z) ^ pcg_hash(seed))));
}

const float INV_2_POW_24 = 1.0 / 16777216.0;
float hash_to_unit(uint h) { return float(h >> 8u) * INV_2_POW_24; }

const float NOISE_CELL_LIMIT = 1073741824.0;
int noise_cell(float floored) {
  return int(dm_clamp(floored, -NOISE_CELL_LIMIT, NOISE_CELL_LIMIT));
}

float noise_fade(float t) { return t * t * (3.0 - 2.0 * t); }

float value_noise(vec2 p, uint seed) {
  precise float fx = floor(p.x), fy = floor(p.y);
  precise float ux = noise_fade(p.x - fx), uy = noise_fade(p.y - fy);
  int ix = noise_cell(fx), iy = noise_cell(fy);
  precise float a = hash_to_unit(hash2i(ix, iy, seed));
  precise float b = hash_to_unit(hash2i(ix + 1, iy, seed));
  precise float c = hash_to_unit(hash2i(ix, iy + 1, seed));
  precise float d = hash_to_unit(hash2i(ix + 1, iy + 1, seed));
  return dm_mix(dm_mix(a, b, ux), dm_mix(c, d, ux), uy);
}

float value_noise(vec3 p, uint seed) {
  precise float fx = floor(p.x), fy = floor(p.y), fz = floor(p.z);
  precise float ux = noise_fade(p.x - fx), uy = noise_fade(p.y - fy), uz = noise_fade(p.z - fz);
  int ix = noise_cell(fx), iy = noise_cell(fy), iz = noise_cell(fz);
  float layer[2];
  for (int k = 0; k < 2; ++k) {
    precise float a = hash_to_unit(hash3i(ix, iy, iz + k, seed));
    precise float b = hash_to_unit(hash3i(ix + 1, iy, iz + k, seed));
    precise float c = hash_to_unit(hash3i(ix, iy + 1, iz + k, seed));
    precise float d = hash_to_unit(hash3i(ix + 1, iy + 1, iz + k, seed));
    layer[k] = dm_mix(dm_mix(a, b, ux), dm_mix(c, d, ux), uy);
  }
  return dm_mix(layer[0], layer[1], uz);
}

const float FBM_LACUNARITY = 2.0;
const float FBM_GAIN = 0.5;
const float FBM_SHIFT = 17.31;

float fbm(vec2 p, int octaves, uint seed) {
  precise float sum = 0.0, amp = 0.5, norm = 0.0;
  for (int i = 0; i < octaves; ++i) {
    sum += amp * value_noise(p, seed + uint(i));
    norm += amp;
    p = p * FBM_LACUNARITY + vec2(FBM_SHIFT);
    amp *= FBM_GAIN;
  }
  return norm > 0.0 ? sum / norm : 0.0;
}

float fbm(vec3 p, int octaves, uint seed) {
  precise float sum = 0.0, amp = 0.5, norm = 0.0;
  for (int i = 0; i < octaves; ++i) {
    sum += amp * value_noise(p, seed + uint(i));
    norm += amp;
    p = p * FBM_LACUNARITY + vec3(FBM_SHIFT);
    amp *= FBM_GAIN;
  }
  return norm > 0.0 ? sum / norm : 0.0;
}

vec2 worley(vec2 p, uint seed) {
  precise float fx = floor(p.x), fy = floor(p.y);
  precise vec2 f = vec2(p.x - fx, p.y - fy);
  int ix = noise_cell(fx), iy = noise_cell(fy);
  precise float f1 = 1e10, f2 = 1e10;
  for (int j = -1; j <= 1; ++j)
    for (int i = -1; i <= 1; ++i) {
      uint h = hash2i(ix + i, iy + j, seed);
      precise vec2 feature = vec2(float(i) + hash_to_unit(h), float(j) + hash_to_unit(pcg_hash(h)));
      precise float d2 = dot2(feature - f);
      if (d2 < f1) {
        f2 = f1;
        f1 = d2;
      } else if (d2 < f2) {
        f2 = d2;
      }
    }
  return vec2(sqrt(f1), sqrt(f2));
}

vec2 worley(vec3 p, uint seed) {
  precise float fx = floor(p.x), fy = floor(p.y), fz = floor(p.z);
  precise vec3 f = vec3(p.x - fx, p.y - fy, p.z - fz);
  int ix = noise_cell(fx), iy = noise_cell(fy), iz = noise_cell(fz);
  precise float f1 = 1e10, f2 = 1e10;
  for (int k = -1; k <= 1; ++k)
    for (int j = -1; j <= 1; ++j)
      for (int i = -1; i <= 1; ++i) {
        uint h = hash3i(ix + i, iy + j, iz + k, seed);
        uint h2 = pcg_hash(h);
        precise vec3 feature = vec3(float(i) + hash_to_unit(h), float(j) + hash_to_unit(h2),
                            float(k) + hash_to_unit(pcg_hash(h2)));
        precise float d2 = dot2(feature - f);
        if (d2 < f1) {
          f2 = f1;
          f1 = d2;
        } else if (d2 < f2) {
          f2 = d2;
        }
      }
  return vec2(sqrt(f1), sqrt(f2));
}
