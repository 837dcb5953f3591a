#include "bench/metrics.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace sdfreel::bench {

namespace {

constexpr double DISPLAY_MAX = 65535.0;
constexpr double P99 = 0.99;

}  // namespace

double psnr_from_rmse(double rmse) {
  if (rmse <= 0.0) return std::numeric_limits<double>::infinity();
  return -20.0 * std::log10(rmse);
}

void ErrorAccumulator::add(const ImageRGB16& image, const ImageRGB16& reference) {
  if (image.width != reference.width || image.height != reference.height ||
      image.pixels.size() != reference.pixels.size())
    throw std::invalid_argument("error metrics: image and reference differ in size");
  abs_errors_.reserve(abs_errors_.size() + image.pixels.size());
  for (size_t i = 0; i < image.pixels.size(); ++i) {
    const double d = (double(image.pixels[i]) - double(reference.pixels[i])) / DISPLAY_MAX;
    sum_sq_ += d * d;
    sum_abs_ += std::abs(d);
    abs_errors_.push_back(float(std::abs(d)));
  }
}

ErrorMetrics ErrorAccumulator::result() const {
  ErrorMetrics m;
  if (abs_errors_.empty()) return m;
  const double n = double(abs_errors_.size());
  m.rmse = std::sqrt(sum_sq_ / n);
  m.psnr_db = psnr_from_rmse(m.rmse);
  m.mean_abs_error = sum_abs_ / n;
  // Nearest rank: the smallest value with at least 99% of the values at or below it.
  std::vector<float> sorted = abs_errors_;
  const size_t rank = size_t(std::ceil(P99 * n));
  const size_t k = rank == 0 ? 0 : rank - 1;
  std::nth_element(sorted.begin(), sorted.begin() + long(k), sorted.end());
  m.p99_abs_error = sorted[k];
  return m;
}

void HitMissAccumulator::add(const ImageRGBA& mask, const ImageRGBA& reference_mask) {
  if (mask.width != reference_mask.width || mask.height != reference_mask.height)
    throw std::invalid_argument("hit/miss: mask and reference differ in size");
  const size_t n = size_t(mask.width) * size_t(mask.height);
  for (size_t i = 0; i < n; ++i)
    if (mask.pixels[i * 4] != reference_mask.pixels[i * 4]) ++differ_;
  pixels_ += n;
}

}  // namespace sdfreel::bench
