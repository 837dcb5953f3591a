#pragma once
// How far two methods' samples agree: same triangle (or both nothing), one drew and the other did
// not, or different triangles, split into depth ties (coplanar faces, shared edges: the two
// triangles are at the same depth there, so the picture hardly changes) and real differences; and
// for samples with the same triangle, how far their depths differ.
#include <cstddef>
#include <vector>

#include "render/camera_model.h"
#include "sample_hits.h"

namespace sdfreel::mesh_bench {

struct Agreement {
  size_t samples = 0, same = 0, hit_vs_miss = 0, tie = 0, other = 0;
  size_t other_alpha = 0;          // of `other`: both triangles from passes with alpha discard
  double max_depth_diff = 0.0;     // |z_w a - z_w b|, same triangle
  double max_relative_view = 0.0;  // |d a - d b| / d in view depth, same triangle
  double same_fraction() const { return samples ? double(same) / double(samples) : 1.0; }
};

// Different triangles within this relative view depth count as a tie.
constexpr double TIE_RELATIVE_DEPTH = 1e-4;

// alpha_pass: per triangle id, whether its pass has alpha discard (empty: none has).
Agreement compare(const SampleHits& a, const SampleHits& b, const CameraModel& camera,
                  const std::vector<bool>& alpha_pass = {});

// Same ids and the same depth bits everywhere (determinism checks).
bool bit_identical(const SampleHits& a, const SampleHits& b);
// Samples whose id or depth bits differ.
size_t differing_samples(const SampleHits& a, const SampleHits& b);
// Same depth bits everywhere (ids ignored).
bool same_depth_bits(const SampleHits& a, const SampleHits& b);

}  // namespace sdfreel::mesh_bench
