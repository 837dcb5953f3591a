#include "osmesa/image_compare.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <vector>

namespace sdfreel::test {

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

}  // namespace sdfreel::test
