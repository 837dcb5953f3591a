#include "agreement.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace sdfreel::mesh_bench {

Agreement compare(const SampleHits& a, const SampleHits& b, const CameraModel& camera,
                  const std::vector<bool>& alpha_pass) {
  Agreement g;
  g.samples = a.id.size();
  for (size_t i = 0; i < a.id.size(); ++i) {
    const bool ha = a.id[i] != 0, hb = b.id[i] != 0;
    if (ha != hb) {
      ++g.hit_vs_miss;
      continue;
    }
    if (!ha) {
      ++g.same;
      continue;
    }
    const double da = view_depth(camera, a.depth[i]), db = view_depth(camera, b.depth[i]);
    const double relative = std::abs(da - db) / std::max(da, db);
    if (a.id[i] == b.id[i]) {
      ++g.same;
      g.max_depth_diff = std::max(g.max_depth_diff, double(std::abs(a.depth[i] - b.depth[i])));
      g.max_relative_view = std::max(g.max_relative_view, relative);
    } else if (relative <= TIE_RELATIVE_DEPTH) {
      ++g.tie;
    } else {
      ++g.other;
      if (!alpha_pass.empty() && alpha_pass[a.id[i] - 1] && alpha_pass[b.id[i] - 1])
        ++g.other_alpha;
    }
  }
  return g;
}

size_t differing_samples(const SampleHits& a, const SampleHits& b) {
  size_t n = 0;
  for (size_t i = 0; i < a.id.size(); ++i)
    n += a.id[i] != b.id[i] || std::memcmp(&a.depth[i], &b.depth[i], sizeof(float)) != 0;
  return n;
}

bool same_depth_bits(const SampleHits& a, const SampleHits& b) {
  return a.depth.size() == b.depth.size() &&
         std::memcmp(a.depth.data(), b.depth.data(), a.depth.size() * sizeof(float)) == 0;
}

bool bit_identical(const SampleHits& a, const SampleHits& b) {
  return a.id == b.id && same_depth_bits(a, b);
}

}  // namespace sdfreel::mesh_bench
