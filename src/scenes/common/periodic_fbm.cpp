#include "scenes/common/periodic_fbm.h"

#include "scenes/common/texture.h"
#include "sdf/noise.h"

namespace sdfreel {

namespace {

// Value noise on a lattice that wraps after (period_x, period_y) cells, so the result tiles.
float periodic_value_noise(float x, float y, int period_x, int period_y, uint32_t seed) {
  const float fx = dm::floor(x), fy = dm::floor(y);
  const float ux = noise_fade(x - fx), uy = noise_fade(y - fy);
  const int ix0 = wrap_texel(fx, period_x), iy0 = wrap_texel(fy, period_y);
  const int ix1 = (ix0 + 1) % period_x, iy1 = (iy0 + 1) % period_y;
  const float a = hash_to_unit(hash2i(ix0, iy0, seed)), b = hash_to_unit(hash2i(ix1, iy0, seed));
  const float c = hash_to_unit(hash2i(ix0, iy1, seed)), d = hash_to_unit(hash2i(ix1, iy1, seed));
  return dm::mix(dm::mix(a, b, ux), dm::mix(c, d, ux), uy);
}

}  // namespace

float periodic_fbm2(float x, float y, int cells_x, int cells_y, int octaves, uint32_t seed) {
  float sum = 0.0f, amp = 0.5f, norm = 0.0f;
  for (int i = 0; i < octaves; ++i) {
    sum += amp * periodic_value_noise(x * float(cells_x), y * float(cells_y), cells_x, cells_y,
                                      seed + uint32_t(i));
    norm += amp;
    cells_x *= 2;
    cells_y *= 2;
    amp *= FBM_GAIN;
  }
  return norm > 0.0f ? sum / norm : 0.0f;
}

float periodic_fbm(float x, float y, int cells, int octaves, uint32_t seed) {
  return periodic_fbm2(x, y, cells, cells, octaves, seed);
}

}  // namespace sdfreel
