#pragma once
// Error of a render against its reference, on display values (what a viewer sees): 16-bit display
// RGB scaled to [0, 1]. Accumulated over the frames of a bench case, then summarised.
#include <cstdint>
#include <vector>

#include "render/image.h"

namespace sdfreel::bench {

struct ErrorMetrics {
  double rmse = 0.0;
  double psnr_db = 0.0;  // 20 log10(1 / rmse); +infinity for identical images
  double mean_abs_error = 0.0;
  double p99_abs_error = 0.0;  // 99th percentile of |difference| over every channel value
};

class ErrorAccumulator {
 public:
  // Adds one frame; throws std::invalid_argument when the sizes differ.
  void add(const ImageRGB16& image, const ImageRGB16& reference);
  ErrorMetrics result() const;
  size_t values() const { return abs_errors_.size(); }

 private:
  std::vector<float> abs_errors_;
  double sum_sq_ = 0.0, sum_abs_ = 0.0;
};

// Counts pixels whose hit ids differ between two MarchSettings::hit_mask renders (red channel:
// 0 = no marched surface, 1, 2, ... = which one).
class HitMissAccumulator {
 public:
  void add(const ImageRGBA& mask, const ImageRGBA& reference_mask);
  double fraction() const { return pixels_ ? double(differ_) / double(pixels_) : 0.0; }

 private:
  uint64_t differ_ = 0, pixels_ = 0;
};

// PSNR in dB of a root-mean-square error on a [0, 1] scale.
double psnr_from_rmse(double rmse);

}  // namespace sdfreel::bench
