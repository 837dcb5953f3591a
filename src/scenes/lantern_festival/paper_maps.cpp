// The paper's tiling normal-noise and value-noise maps (the seed sampled image files instead).
#include <cstddef>

#include "scenes/common/periodic_fbm.h"
#include "scenes/lantern_festival/generated_textures.h"
#include "sdf/noise.h"

namespace sdfreel::lantern_festival {

namespace {

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
