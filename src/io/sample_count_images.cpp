#include "io/sample_count_images.h"

#include <algorithm>
#include <cmath>

namespace sdfreel {

namespace {

// A dark-to-bright ramp (after matplotlib's "inferno"), linear between its stops.
glm::vec3 heat(float t) {
  static const glm::vec3 stops[] = {{0.0f, 0.0f, 0.02f},
                                    {0.26f, 0.04f, 0.41f},
                                    {0.73f, 0.21f, 0.33f},
                                    {0.98f, 0.55f, 0.04f},
                                    {0.99f, 1.0f, 0.64f}};
  const float x = std::clamp(t, 0.0f, 1.0f) * 4.0f;
  const int i = std::min(int(x), 3);
  return glm::mix(stops[i], stops[i + 1], x - float(i));
}

}  // namespace

ImageRGBA sample_count_image(const SampleCounts& counts, int width, int height) {
  ImageRGBA img(width, height);
  for (size_t i = 0; i < counts.size() && i * 4 < img.pixels.size(); ++i) {
    float* p = &img.pixels[i * 4];
    p[0] = p[1] = p[2] = float(counts[i]);
    p[3] = 1.0f;
  }
  return img;
}

ImageRGB16 sample_heat_map(const SampleCounts& counts, int width, int height, int maximum) {
  ImageRGB16 img(width, height);
  const float top = std::log2(float(std::max(maximum, 2)));
  for (size_t i = 0; i < counts.size() && i * 3 < img.pixels.size(); ++i) {
    const glm::vec3 c = heat(std::log2(float(std::max<int>(counts[i], 1))) / top);
    for (int k = 0; k < 3; ++k) img.pixels[i * 3 + k] = uint16_t(std::lround(c[k] * 65535.0f));
  }
  return img;
}

}  // namespace sdfreel
