#pragma once
// Per-pixel adaptive sampling. A pixel takes the frame's sample offsets (the R2 list of
// `maximum` offsets) in list order, in rounds: `minimum` samples first, then ADAPTIVE_ROUND more
// at a time, until its own error estimate falls under `threshold` or it reaches `maximum`. The
// estimate reads only the pixel's own sums, so which samples a pixel takes never depends on
// threads, tiles, shards or backend, and its samples are summed in list order as fixed sampling
// sums them: with threshold 0 every pixel takes `maximum`, the bits of fixed `maximum` samples.
//
// The estimate: the means of the pixel's even-indexed and odd-indexed samples, each put through a
// cheap display curve (sqrt(x / (1 + x)) per channel, close to a tone-mapped sRGB value), differ
// by about twice the standard error of the pixel's mean; the estimate is half the largest
// channel difference. Both backends compute it on the host from the same float sums.
#include <glm/glm.hpp>
#include <string>

namespace sdfreel {

constexpr int ADAPTIVE_ROUND = 2;  // samples a round adds after the first: one even, one odd

struct AdaptiveSampling {
  bool enabled = false;
  int minimum = 2, maximum = 16;  // 1 <= minimum <= maximum <= 1024
  float threshold = 0.0f;         // display-space standard error; 0 = always `maximum`
};

// Samples taken before the first decision: `minimum`.
int first_round_samples(const AdaptiveSampling& a);
// Samples a pixel has after the round that follows `taken` samples.
int next_round_end(const AdaptiveSampling& a, int taken);
// The pixel's error estimate from the sums of its `taken` samples: all of them, and those at odd
// list positions (1, 3, 5...). Infinite when taken < 2 (nothing to compare).
float adaptive_error(int taken, const glm::vec3& sum, const glm::vec3& sum_odd);
// After `taken` samples: does the pixel take another round?
bool needs_more_samples(const AdaptiveSampling& a, int taken, const glm::vec3& sum,
                        const glm::vec3& sum_odd);
// "minimum=2 maximum=16 threshold=0.005" (shortest round-trip numbers), for manifests and logs.
std::string adaptive_text(const AdaptiveSampling& a);

}  // namespace sdfreel
