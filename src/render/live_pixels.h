#pragma once
// Adaptive sampling over a whole frame, for runners that take one sample of every pixel at a
// time (the CPU's per-sample plan loop, the GL runner): every live pixel has taken the same
// samples, so at the end of each round (render/adaptive_sampling.h) one pass over the frame's
// sums decides which pixels go on.
#include <cstdint>
#include <vector>

#include "render/adaptive_sampling.h"
#include "render/image.h"

namespace sdfreel {

// Samples each pixel took, row-major, top row first.
using SampleCounts = std::vector<uint16_t>;

class LivePixels {
 public:
  LivePixels(const AdaptiveSampling& a, int width, int height);
  // True when a round ends after sample `taken` (a count), so decide() is due.
  bool round_ends_at(int taken) const;
  // After `taken` samples summed into `sum` and `sum_odd` (odd list positions only): pixels that
  // need no more stop. Returns how many pixels are still live.
  int decide(int taken, const ImageRGBA& sum, const ImageRGBA& sum_odd);
  bool live(size_t pixel) const { return live_[pixel] != 0; }
  const std::vector<uint8_t>& mask() const { return live_; }
  const SampleCounts& counts() const { return taken_; }

 private:
  AdaptiveSampling a_;
  int next_end_;
  std::vector<uint8_t> live_;
  SampleCounts taken_;  // `maximum` until the pixel stops
};

// The frame: each pixel's sum times 1 / its count (as fixed sampling's 1 / count), alpha 1.
void normalise_sums(ImageRGBA& sum, const SampleCounts& counts);

}  // namespace sdfreel
