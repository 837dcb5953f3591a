// The paper's tiling normal-noise and value-noise maps (the seed sampled image files instead).
#include <cstddef>

#include "scenes/lantern_festival/generated_textures.h"
#include "sdf/noise.h"

namespace sdfreel::lantern_festival {

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

// Fractal sum with separate lattice sizes in x and y (stretched lattices make fibres).
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

// Paper height: soft cloudy fbm plus thin fibres stretched along the lantern's circumference.
constexpr int PAPER_CLOUD_CELLS = 6;
constexpr int PAPER_FIBRE_CELLS_X = 4;
constexpr int PAPER_FIBRE_CELLS_Y = 40;
constexpr float PAPER_FIBRE_WEIGHT = 0.45f;
// Scales the height field's slope (per texture period) into the tangent-space normal's tilt.
constexpr float PAPER_NORMAL_STRENGTH = 0.03f;
// The albedo noise: blotches, contrast-stretched so that noise * 0.4 visibly mottles the paper.
constexpr int PAPER_BLOTCH_CELLS = 5;
constexpr float PAPER_BLOTCH_LO = 0.35f, PAPER_BLOTCH_HI = 0.75f;

float paper_height(float u, float v, uint32_t seed) {
  const float cloud = periodic_fbm2(u, v, PAPER_CLOUD_CELLS, PAPER_CLOUD_CELLS, 5, seed);
  const float fibre = periodic_fbm2(u, v, PAPER_FIBRE_CELLS_X, PAPER_FIBRE_CELLS_Y, 3, seed + 101u);
  return cloud + PAPER_FIBRE_WEIGHT * fibre;
}

}  // namespace

float periodic_fbm(float x, float y, int cells, int octaves, uint32_t seed) {
  return periodic_fbm2(x, y, cells, cells, octaves, seed);
}

Texture make_paper_normal_map(int n, uint32_t seed) {
  std::vector<float> h(size_t(n) * n);
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x)
      h[size_t(y) * n + x] =
          paper_height((float(x) + 0.5f) / float(n), (float(y) + 0.5f) / float(n), seed);
  Texture t(n, n, 3);
  const float texel = 1.0f / float(n);
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      // Central differences on the torus: the map tiles without a seam.
      const float dhdx =
          (h[size_t(y) * n + (x + 1) % n] - h[size_t(y) * n + (x + n - 1) % n]) / (2.0f * texel);
      const float dhdy =
          (h[size_t((y + 1) % n) * n + x] - h[size_t((y + n - 1) % n) * n + x]) / (2.0f * texel);
      const glm::vec3 slope(-dhdx * PAPER_NORMAL_STRENGTH, -dhdy * PAPER_NORMAL_STRENGTH, 1.0f);
      const glm::vec3 nrm = slope / dm::sqrt(glm::dot(slope, slope));
      float* c = t.at(x, y);
      c[0] = nrm.x * 0.5f + 0.5f;
      c[1] = nrm.y * 0.5f + 0.5f;
      c[2] = nrm.z * 0.5f + 0.5f;
    }
  return t;
}

Texture make_paper_noise_map(int n, uint32_t seed) {
  Texture t(n, n, 1);
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const float v = periodic_fbm((float(x) + 0.5f) / float(n), (float(y) + 0.5f) / float(n),
                                   PAPER_BLOTCH_CELLS, 5, seed + 7u);
      *t.at(x, y) = dm::smoothstep(PAPER_BLOTCH_LO, PAPER_BLOTCH_HI, v);
    }
  return t;
}

}  // namespace sdfreel::lantern_festival
