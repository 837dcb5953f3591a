#pragma once
// The backend agreement metric: differences of display values (in 1/255 units), summarised by
// their mean and a high percentile, because ray marching flips a few silhouette pixels between
// backends and a maximum would only measure those.
#include <string>

#include "render/image.h"

namespace sdfreel::test {

struct DisplayDifference {
  double mean = 0.0;             // mean over pixels of the largest channel difference, in 1/255
  double p999 = 0.0;             // 99.9th percentile of the same
  double max = 0.0;              // for the report only
  double identical_share = 0.0;  // share of pixels with equal 16-bit values in all channels
};

DisplayDifference compare_display(const ImageRGB16& a, const ImageRGB16& b);

// |a - b| per channel, scaled by `gain` and clamped: a picture of where the backends disagree.
ImageRGB16 difference_image(const ImageRGB16& a, const ImageRGB16& b, double gain);

}  // namespace sdfreel::test
