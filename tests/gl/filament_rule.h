#pragma once
// Filament's renderer-test rule (io/display_compare.h) for frames with mesh passes (which need not
// be bit-identical between backends): at most 0.1% of display pixels off by more than 5/255 and a
// mean difference below 0.5/255, on display values (clamped, 1/2.2 power, 16 bits); diff images
// written on failure.
#include <string>

#include "io/display_compare.h"
#include "render/image.h"

namespace sdfreel::test {

ImageRGB16 filament_display(const ImageRGBA& linear);

struct FilamentVerdict {
  double mean = 0.0, share_over_5 = 0.0, max = 0.0;
  bool pass = false;
  std::string images;  // where cpu.png, gl.png and diff.png went ("" when not written)
};

// Compares two linear frames by the rule; writes the images into `dir_name` under
// SDFREEL_TEST_IMAGES (always) or the test temp dir (on failure).
FilamentVerdict filament_compare(const ImageRGBA& cpu, const ImageRGBA& gl,
                                 const std::string& dir_name);

}  // namespace sdfreel::test
