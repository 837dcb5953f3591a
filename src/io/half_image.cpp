#include "io/half_image.h"

#include <Imath/half.h>

#ifdef __F16C__
#include <immintrin.h>
#endif

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
  float* v = img.pixels.data();
  const size_t n = img.pixels.size();
  size_t i = 0;
#ifdef __F16C__
  // Eight values an instruction. max(0, x) and min(65504, x) keep the scalar line's choices
  // exactly (-0 stays -0, a NaN stays NaN: the operand order picks x when the compare is false).
  const __m256 zero = _mm256_setzero_ps(), largest = _mm256_set1_ps(65504.0f);
  for (; i + 8 <= n; i += 8) {
    const __m256 c = _mm256_min_ps(largest, _mm256_max_ps(zero, _mm256_loadu_ps(v + i)));
    _mm256_storeu_ps(v + i, _mm256_cvtph_ps(_mm256_cvtps_ph(c, _MM_FROUND_TO_NEAREST_INT)));
  }
#endif
  for (; i < n; ++i) {
    const float c = v[i] < 0.0f ? 0.0f : (v[i] > 65504.0f ? 65504.0f : v[i]);
    v[i] = float(Imath::half(c));
  }
}

}  // namespace sdfreel
