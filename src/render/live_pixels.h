#pragma once
// Adaptive sampling over a whole frame (render/adaptive_sampling.h): every live pixel has taken
// the same samples, so at the end of each round one pass over the frame's finished sums decides
// which pixels go on. The CPU's resolved ray pass, its per-sample plan loop and the GL runner all
// decide here, from the same float sums: the same pixels stop on every backend.
#include <cstdint>
#include <vector>

#include "render/adaptive_sampling.h"
#include "render/image.h"

namespace sdfreel {

// Samples each pixel took, row-major, top row first.
using SampleCounts = std::vector<uint16_t>;

class LivePixels {
 public:
  // threads: how many decide() may use (render/tiling.h; 0: automatic); rows decide on their own,
  // so the result never depends on it.
  LivePixels(const AdaptiveSampling& a, int width, int height, int threads);
  // The sample count at which the current round ends.
  int round_end() const { return next_end_; }
  // True when a round ends after sample `taken` (a count), so decide() is due.
  bool round_ends_at(int taken) const;
  // After `taken` samples summed into `sum` and `sum_odd` (odd list positions only; stopped
  // pixels keep the sums they stopped with): pixels that need no more stop. Returns how many
  // pixels are still live.
  int decide(int taken, const ImageRGBA& sum, const ImageRGBA& sum_odd);
  bool live(size_t pixel) const { return live_[pixel] != 0; }
  // No pixel has stopped yet (fixed sampling, or before the first decision that stops one).
  bool all_live() const { return all_live_; }
  // Whether decide() will be due again (never for fixed sampling): else the odd samples' sums,
  // which only decisions read, need not be kept.
  bool decides() const { return next_end_ < a_.maximum; }
  const std::vector<uint8_t>& mask() const { return live_; }
  const SampleCounts& counts() const { return taken_; }

 private:
  float contrast(int x, int y) const;

  AdaptiveSampling a_;
  int width_, height_, threads_, next_end_;
  bool all_live_ = true;
  std::vector<uint8_t> live_;
  SampleCounts taken_;              // `maximum` until the pixel stops
  std::vector<glm::vec3> display_;  // each pixel's mean at its last round, display values;
                                    // sized at the first decision
};

// The frame: each pixel's sum times 1 / its count (as fixed sampling's 1 / count), alpha 1; on
// `threads` threads (render/tiling.h), each pixel on its own.
void normalise_sums(ImageRGBA& sum, const SampleCounts& counts, int threads);

}  // namespace sdfreel
