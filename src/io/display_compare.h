#pragma once
// Differences of display values (in 1/255 units), summarised by their mean and a high percentile,
// because ray marching flips a few silhouette pixels between renderers and a maximum would only
// measure those; and Filament's renderer-test rule on them, for frames that need not be
// bit-identical (a GPU against llvmpipe or the CPU; mesh passes between backends).
#include <string>

#include "render/image.h"

namespace sdfreel {

struct DisplayDifference {
  double mean = 0.0;             // mean over pixels of the largest channel difference, in 1/255
  double p999 = 0.0;             // 99.9th percentile of the same
  double max = 0.0;              // for the report only
  double identical_share = 0.0;  // share of pixels with equal 16-bit values in all channels
};

DisplayDifference compare_display(const ImageRGB16& a, const ImageRGB16& b);

// |a - b| per channel, scaled by `gain` and clamped: a picture of where the backends disagree.
ImageRGB16 difference_image(const ImageRGB16& a, const ImageRGB16& b, double gain);

// Filament's rule: at most 0.1% of pixels off by more than 5/255, and a mean under 0.5/255.
constexpr double FILAMENT_MAX_SHARE_OVER_5 = 0.001;
constexpr double FILAMENT_MAX_MEAN = 0.5;  // in 1/255

// Share of pixels whose largest channel difference exceeds limit_255 (in 1/255).
double share_over(const ImageRGB16& a, const ImageRGB16& b, double limit_255);

struct ToleranceVerdict {
  DisplayDifference difference;
  double share_over_5 = 0.0;
  double psnr_db = 0.0;  // of display values in [0, 1]; infinity when equal
  bool pass = false;
};

// Throws std::invalid_argument when the images differ in size.
ToleranceVerdict filament_rule(const ImageRGB16& reference, const ImageRGB16& frame);

}  // namespace sdfreel
