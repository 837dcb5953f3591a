#pragma once
// The sample-count AOV of adaptive sampling (render/live_pixels.h): the samples each pixel took,
// as exact values (every channel of a float image, for EXR: half holds integers up to 2048
// exactly) or as a heat map for people (dark blue at the fewest samples, through red, to yellow
// at `maximum`, on a log scale so that 2, 4, 8 and 16 are evenly spaced).
#include "render/image.h"
#include "render/live_pixels.h"

namespace sdfreel {

ImageRGBA sample_count_image(const SampleCounts& counts, int width, int height);
ImageRGB16 sample_heat_map(const SampleCounts& counts, int width, int height, int maximum);

}  // namespace sdfreel
