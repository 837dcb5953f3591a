#include "io/half_image.h"

#include <Imath/half.h>

#include <cmath>

namespace sdfreel {

std::optional<std::string> find_non_finite(const ImageRGBA& img) {
  static const char* names = "RGBA";
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x)
      for (int c = 0; c < 4; ++c) {
        const float v = img.at(x, y)[c];
        if (!std::isfinite(v))
          return "pixel (" + std::to_string(x) + ", " + std::to_string(y) + ") channel " +
                 names[c] + " is " + (std::isnan(v) ? "NaN" : "infinite");
      }
  return std::nullopt;
}

size_t zero_non_finite(ImageRGBA& img, std::string* first) {
  if (first)
    if (auto bad = find_non_finite(img)) *first = *bad;
  size_t count = 0;
  for (float& v : img.pixels)
    if (!std::isfinite(v)) v = 0.0f, ++count;
  return count;
}

void round_to_half(ImageRGBA& img) {
  for (float& v : img.pixels) {
    const float c = v < 0.0f ? 0.0f : (v > 65504.0f ? 65504.0f : v);
    v = float(Imath::half(c));
  }
}

}  // namespace sdfreel
