#include "io/display_compare.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <stdexcept>
#include <vector>

namespace sdfreel {

DisplayDifference compare_display(const ImageRGB16& a, const ImageRGB16& b) {
  if (a.width != b.width || a.height != b.height || a.pixels.size() != b.pixels.size() ||
      a.pixels.empty())
    throw std::invalid_argument("compare_display: images differ in size or are empty");
  const size_t n = a.pixels.size() / 3;
  std::vector<double> diffs(n);
  double sum = 0.0;
  size_t identical = 0;
  for (size_t i = 0; i < n; ++i) {
    int worst = 0;
    for (int c = 0; c < 3; ++c)
      worst = std::max(worst, std::abs(int(a.pixels[i * 3 + c]) - int(b.pixels[i * 3 + c])));
    diffs[i] = worst * (255.0 / 65535.0);
    sum += diffs[i];
    identical += worst == 0;
  }
  DisplayDifference d;
  d.mean = sum / double(n);
  d.identical_share = double(identical) / double(n);
  std::sort(diffs.begin(), diffs.end());
  // Nearest-rank percentile.
  const size_t rank = size_t(std::ceil(0.999 * double(n)));
  d.p999 = diffs[std::min(n - 1, rank > 0 ? rank - 1 : 0)];
  d.max = diffs.back();
  return d;
}

ImageRGB16 difference_image(const ImageRGB16& a, const ImageRGB16& b, double gain) {
  ImageRGB16 out(a.width, a.height);
  for (size_t i = 0; i < out.pixels.size() && i < b.pixels.size(); ++i) {
    const double d = std::abs(double(a.pixels[i]) - double(b.pixels[i])) * gain;
    out.pixels[i] = uint16_t(std::min(d, 65535.0));
  }
  return out;
}

double share_over(const ImageRGB16& a, const ImageRGB16& b, double limit_255) {
  size_t over = 0;
  for (size_t i = 0; i < a.pixels.size(); i += 3) {
    int worst = 0;
    for (int c = 0; c < 3; ++c)
      worst =
          std::max(worst, std::abs(int(a.pixels[i + size_t(c)]) - int(b.pixels[i + size_t(c)])));
    over += worst * (255.0 / 65535.0) > limit_255;
  }
  return double(over) / double(a.pixels.size() / 3);
}

ToleranceVerdict filament_rule(const ImageRGB16& reference, const ImageRGB16& frame) {
  ToleranceVerdict v;
  v.difference = compare_display(reference, frame);
  v.share_over_5 = share_over(reference, frame, 5.0);
  double squared = 0.0;
  for (size_t i = 0; i < frame.pixels.size(); ++i) {
    const double d = (double(reference.pixels[i]) - double(frame.pixels[i])) / 65535.0;
    squared += d * d;
  }
  const double mse = squared / double(frame.pixels.size());
  v.psnr_db = mse > 0.0 ? -10.0 * std::log10(mse) : std::numeric_limits<double>::infinity();
  v.pass = v.share_over_5 <= FILAMENT_MAX_SHARE_OVER_5 && v.difference.mean < FILAMENT_MAX_MEAN;
  return v;
}

}  // namespace sdfreel
