#pragma once
// Per-pixel adaptive sampling. A pixel takes the frame's sample offsets (the R2 list of
// `maximum` offsets) in list order, in rounds: `minimum` samples first, then ADAPTIVE_ROUND more
// at a time, until its error estimate falls under `threshold` or it reaches `maximum`. Rounds are
// frame-wide: after each, one pass over the frame's finished sums decides which pixels go on
// (render/live_pixels.h), so which samples a pixel takes never depends on threads, tiles, shards
// or backend, and its samples are summed in list order as fixed sampling sums them: with
// threshold 0 every pixel takes `maximum`, the bits of fixed `maximum` samples.
//
// The estimate is the larger of two, both on display values (each channel of a mean through
// sqrt(x / (1 + x)), close to a tone-mapped sRGB value):
// - the pixel's own: half the largest channel difference between the means of its even-indexed
//   and odd-indexed samples, about its standard error (0 below two samples: nothing to compare);
// - the edge estimate: EDGE_WEIGHT * contrast / samples, with contrast the largest channel
//   difference between the pixel's mean and one of its eight neighbours'. A strut, star or glint
//   that both of a pixel's first samples miss leaves the pixel flat but its neighbours different,
//   and an edge's coverage error shrinks about as 1 / samples for R2 points.
#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>
#include <string>

namespace sdfreel {

constexpr int ADAPTIVE_ROUND = 2;  // samples a round adds after the first: one even, one odd
// Weight of the edge estimate. Measured on the lanterns at 320x180 (bench): 0.5 and 1 lie on one
// error-against-cost curve, 0.25 below it; ending the edge estimate at 4 or 8 samples costs more
// error than it saves time.
constexpr float EDGE_WEIGHT = 0.5f;

struct AdaptiveSampling {
  bool enabled = false;
  int minimum = 2, maximum = 16;  // 1 <= minimum <= maximum <= 1024
  float threshold = 0.0f;         // display-space error; 0 = always `maximum`
};

// Samples taken before the first decision: `minimum`.
int first_round_samples(const AdaptiveSampling& a);
// Samples a pixel has after the round that follows `taken` samples.
int next_round_end(const AdaptiveSampling& a, int taken);
// A linear mean's display value, per channel sqrt(x / (1 + x)) (negative values as 0).
glm::vec3 display_value(const glm::vec3& mean);
// The largest channel difference of two display values (inline: LivePixels::contrast takes nine
// a live pixel every round).
inline float display_difference(const glm::vec3& a, const glm::vec3& b) {
  return std::max(std::fabs(a.x - b.x), std::max(std::fabs(a.y - b.y), std::fabs(a.z - b.z)));
}
// The pixel's own estimate from the sums of its `taken` samples: all of them, and those at odd
// list positions (1, 3, 5...). 0 when taken < 2.
float own_error(int taken, const glm::vec3& sum, const glm::vec3& sum_odd);
// The edge estimate of a pixel of `taken` samples whose largest display difference to a
// neighbour is `contrast`.
float edge_error(int taken, float contrast);
// After `taken` samples with error estimate `error`: does the pixel take another round?
bool needs_more_samples(const AdaptiveSampling& a, int taken, float error);
// "minimum=2 maximum=16 threshold=0.005" (shortest round-trip numbers), for manifests and logs.
std::string adaptive_text(const AdaptiveSampling& a);

}  // namespace sdfreel
