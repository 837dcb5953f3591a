// Void-and-cluster (Ulichney 1993, "The void-and-cluster method for dither array generation").
#include <cstddef>

#include "scenes/lantern_festival/generated_textures.h"
#include "sdf/noise.h"

namespace sdfreel::lantern_festival {

namespace {

// Gaussian energy filter, sigma 1.5 as in the paper; truncated at 8 pixels where it is below 1e-6.
constexpr float VC_SIGMA = 1.5f;
constexpr int VC_RADIUS = 8;
// The initial random pattern holds about a tenth of the pixels.
constexpr int VC_INITIAL_DIVISOR = 10;

class EnergyField {
 public:
  explicit EnergyField(int n) : n_(n), energy_(size_t(n) * n, 0.0f), on_(size_t(n) * n, 0) {
    const int side = 2 * VC_RADIUS + 1;
    kernel_.resize(size_t(side) * side);
    for (int dy = -VC_RADIUS; dy <= VC_RADIUS; ++dy)
      for (int dx = -VC_RADIUS; dx <= VC_RADIUS; ++dx)
        kernel_[size_t(dy + VC_RADIUS) * side + (dx + VC_RADIUS)] =
            dm::exp(-float(dx * dx + dy * dy) / (2.0f * VC_SIGMA * VC_SIGMA));
  }

  bool on(int i) const { return on_[i] != 0; }

  void set(int i, bool value) {
    if (on(i) == value) return;
    on_[i] = value ? 1 : 0;
    const float sign = value ? 1.0f : -1.0f;
    const int side = 2 * VC_RADIUS + 1;
    const int x = i % n_, y = i / n_;
    for (int dy = -VC_RADIUS; dy <= VC_RADIUS; ++dy) {
      const int yy = (y + dy + n_ * VC_RADIUS) % n_;
      for (int dx = -VC_RADIUS; dx <= VC_RADIUS; ++dx) {
        const int xx = (x + dx + n_ * VC_RADIUS) % n_;
        energy_[size_t(yy) * n_ + xx] +=
            sign * kernel_[size_t(dy + VC_RADIUS) * side + (dx + VC_RADIUS)];
      }
    }
  }

  // Tightest cluster: the set pixel with the highest energy (first in index order on ties).
  int tightest_cluster() const {
    int best = -1;
    for (int i = 0; i < int(energy_.size()); ++i)
      if (on_[i] && (best < 0 || energy_[i] > energy_[best])) best = i;
    return best;
  }

  // Largest void: the empty pixel with the lowest energy.
  int largest_void() const {
    int best = -1;
    for (int i = 0; i < int(energy_.size()); ++i)
      if (!on_[i] && (best < 0 || energy_[i] < energy_[best])) best = i;
    return best;
  }

 private:
  int n_;
  std::vector<float> energy_;
  std::vector<unsigned char> on_;
  std::vector<float> kernel_;
};

}  // namespace

std::vector<int> void_and_cluster_ranks(int n, uint32_t seed) {
  const int total = n * n;
  const int initial = total / VC_INITIAL_DIVISOR > 0 ? total / VC_INITIAL_DIVISOR : 1;

  // Random initial pattern from the hash stream of `seed`.
  EnergyField proto(n);
  int placed = 0;
  for (uint32_t k = 0; placed < initial; ++k) {
    const int i = int(pcg_hash(k ^ pcg_hash(seed)) % uint32_t(total));
    if (!proto.on(i)) {
      proto.set(i, true);
      ++placed;
    }
  }
  // Relax it: move the tightest cluster into the largest void until that changes nothing.
  for (int iter = 0; iter < total; ++iter) {
    const int cluster = proto.tightest_cluster();
    proto.set(cluster, false);
    const int hole = proto.largest_void();
    proto.set(hole, true);
    if (hole == cluster) break;
  }

  std::vector<int> rank(size_t(total), 0);
  // Phase 1: remove the initial points tightest-cluster first; they get the ranks below `initial`.
  {
    EnergyField f = proto;
    for (int r = initial - 1; r >= 0; --r) {
      const int c = f.tightest_cluster();
      f.set(c, false);
      rank[c] = r;
    }
  }
  // Phases 2 and 3: fill the largest void until the array is full. (With a fixed kernel the
  // paper's phase 3, "tightest cluster of zeros", is the empty pixel of lowest energy: the same.)
  EnergyField f = proto;
  for (int r = initial; r < total; ++r) {
    const int v = f.largest_void();
    f.set(v, true);
    rank[v] = r;
  }
  return rank;
}

Texture make_blue_noise(int n, int channels, uint32_t seed) {
  Texture t(n, n, channels);
  const float inv = 1.0f / float(n * n);
  for (int c = 0; c < channels; ++c) {
    const std::vector<int> rank =
        void_and_cluster_ranks(n, pcg_hash(seed + uint32_t(c) * 0x9e3779b9u));
    for (int i = 0; i < n * n; ++i)
      t.texels[size_t(i) * channels + c] = (float(rank[i]) + 0.5f) * inv;
  }
  return t;
}

}  // namespace sdfreel::lantern_festival
