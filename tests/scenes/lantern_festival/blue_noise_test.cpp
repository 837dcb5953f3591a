// The lantern scene's generated textures: void-and-cluster blue noise (a permutation with a
// blue-noise spectrum), and the paper maps (tiling, deterministic).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

#include "scenes/lantern_festival/generated_textures.h"
#include "sdf/noise.h"

namespace sdfreel::lantern_festival {
namespace {

// Power spectrum of a zero-mean n x n field (separable DFT, double precision).
std::vector<double> power_spectrum(const std::vector<double>& f, int n) {
  std::vector<double> re(f.size()), im(f.size()), re2(f.size()), im2(f.size());
  const double w = 2.0 * M_PI / n;
  for (int y = 0; y < n; ++y)  // rows
    for (int k = 0; k < n; ++k) {
      double a = 0.0, b = 0.0;
      for (int x = 0; x < n; ++x) {
        a += f[y * n + x] * std::cos(w * k * x);
        b -= f[y * n + x] * std::sin(w * k * x);
      }
      re[y * n + k] = a;
      im[y * n + k] = b;
    }
  for (int k = 0; k < n; ++k)  // columns
    for (int l = 0; l < n; ++l) {
      double a = 0.0, b = 0.0;
      for (int y = 0; y < n; ++y) {
        const double c = std::cos(w * l * y), s = std::sin(w * l * y);
        a += re[y * n + k] * c + im[y * n + k] * s;
        b += im[y * n + k] * c - re[y * n + k] * s;
      }
      re2[l * n + k] = a;
      im2[l * n + k] = b;
    }
  std::vector<double> p(f.size());
  for (size_t i = 0; i < p.size(); ++i) p[i] = re2[i] * re2[i] + im2[i] * im2[i];
  return p;
}

// Mean power at radial frequencies in [lo, hi) (cycles per period), DC excluded.
double ring_power(const std::vector<double>& p, int n, double lo, double hi) {
  double sum = 0.0;
  int count = 0;
  for (int l = 0; l < n; ++l)
    for (int k = 0; k < n; ++k) {
      const int fx = k <= n / 2 ? k : k - n, fy = l <= n / 2 ? l : l - n;
      const double r = std::sqrt(double(fx * fx + fy * fy));
      if (r > 0.0 && r >= lo && r < hi) {
        sum += p[l * n + k];
        ++count;
      }
    }
  return sum / count;
}

std::vector<double> centred(const std::vector<int>& rank) {
  std::vector<double> f(rank.size());
  for (size_t i = 0; i < rank.size(); ++i) f[i] = (rank[i] + 0.5) / double(rank.size()) - 0.5;
  return f;
}

TEST(LanternFestivalBlueNoise, RanksArePermutation) {
  const int n = 32;
  std::vector<int> r = void_and_cluster_ranks(n, 7u);
  std::sort(r.begin(), r.end());
  for (int i = 0; i < n * n; ++i) ASSERT_EQ(r[i], i);
}

TEST(LanternFestivalBlueNoise, DeterministicPerSeed) {
  EXPECT_EQ(void_and_cluster_ranks(32, 3u), void_and_cluster_ranks(32, 3u));
  EXPECT_NE(void_and_cluster_ranks(32, 3u), void_and_cluster_ranks(32, 4u));
}

TEST(LanternFestivalBlueNoise, LowFrequenciesCarryLittleEnergy) {
  const int n = BLUE_NOISE_SIZE;
  const std::vector<double> blue = power_spectrum(centred(void_and_cluster_ranks(n, 1u)), n);
  // White-noise control: a hashed random permutation of the same ranks.
  std::vector<int> white(n * n);
  std::iota(white.begin(), white.end(), 0);
  for (int i = n * n - 1; i > 0; --i)
    std::swap(white[i], white[pcg_hash(uint32_t(i)) % uint32_t(i + 1)]);
  const std::vector<double> ctrl = power_spectrum(centred(white), n);

  const double low_blue = ring_power(blue, n, 0.0, n / 8.0),
               high_blue = ring_power(blue, n, n / 4.0, n);
  const double low_white = ring_power(ctrl, n, 0.0, n / 8.0),
               high_white = ring_power(ctrl, n, n / 4.0, n);
  // Blue noise: the low band is nearly empty next to the high band. White noise: flat.
  EXPECT_LT(low_blue, 0.1 * high_blue) << low_blue << " vs " << high_blue;
  EXPECT_GT(low_white, 0.5 * high_white) << low_white << " vs " << high_white;
  // And it is not just a rescaling: the low band is far below white noise's.
  EXPECT_LT(low_blue, 0.1 * low_white);
}

TEST(LanternFestivalBlueNoise, TextureChannelsAreIndependentArrays) {
  const Texture t = make_blue_noise(16, 4, 9u);
  ASSERT_EQ(t.channels, 4);
  for (int c = 1; c < 4; ++c) {
    int same = 0;
    for (int i = 0; i < 16 * 16; ++i) same += t.texels[i * 4] == t.texels[i * 4 + c];
    EXPECT_LT(same, 16) << "channel " << c;
  }
  for (float v : t.texels) {
    EXPECT_GT(v, 0.0f);
    EXPECT_LT(v, 1.0f);
  }
}

// The paper maps tile: across the wrap-around seam neighbouring texels differ no more than
// neighbours inside the map do.
double max_neighbour_step(const Texture& t, bool seam) {
  double worst = 0.0;
  for (int y = 0; y < t.height; ++y)
    for (int x = 0; x < t.width; ++x) {
      const bool at_seam = x == t.width - 1;
      if (at_seam != seam) continue;
      const float* a = t.at(x, y);
      const float* b = t.at((x + 1) % t.width, y);
      for (int c = 0; c < t.channels; ++c) worst = std::max(worst, double(std::fabs(a[c] - b[c])));
    }
  return worst;
}

TEST(LanternFestivalPaperMaps, TileWithoutSeam) {
  for (const Texture& t : {make_paper_normal_map(64, 5u), make_paper_noise_map(64, 5u)}) {
    const double inside = max_neighbour_step(t, false), seam = max_neighbour_step(t, true);
    EXPECT_GT(inside, 0.0);
    EXPECT_LE(seam, inside);
  }
}

TEST(LanternFestivalPaperMaps, NormalsAreUnitAndFacingOut) {
  const Texture t = make_paper_normal_map(64, 5u);
  for (int i = 0; i < 64 * 64; ++i) {
    const float x = t.texels[i * 3] * 2 - 1, y = t.texels[i * 3 + 1] * 2 - 1,
                z = t.texels[i * 3 + 2] * 2 - 1;
    EXPECT_NEAR(x * x + y * y + z * z, 1.0f, 1e-4f);
    EXPECT_GT(z, 0.0f);
  }
  EXPECT_EQ(t.texels, make_paper_normal_map(64, 5u).texels);
  EXPECT_NE(t.texels, make_paper_normal_map(64, 6u).texels);
}

}  // namespace
}  // namespace sdfreel::lantern_festival
