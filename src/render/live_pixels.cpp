#include "render/live_pixels.h"

namespace sdfreel {

namespace {

glm::vec3 rgb(const float* p) {
  return glm::vec3(p[0], p[1], p[2]);
}

}  // namespace

LivePixels::LivePixels(const AdaptiveSampling& a, int width, int height)
    : a_(a),
      next_end_(first_round_samples(a)),
      live_(size_t(width) * height, 1),
      taken_(size_t(width) * height, uint16_t(a.maximum)) {}

bool LivePixels::round_ends_at(int taken) const {
  return taken == next_end_ && taken < a_.maximum;
}

int LivePixels::decide(int taken, const ImageRGBA& sum, const ImageRGBA& sum_odd) {
  next_end_ = next_round_end(a_, taken);
  int live = 0;
  for (size_t i = 0; i < live_.size(); ++i) {
    if (!live_[i]) continue;
    if (needs_more_samples(a_, taken, rgb(&sum.pixels[i * 4]), rgb(&sum_odd.pixels[i * 4]))) {
      ++live;
    } else {
      live_[i] = 0;
      taken_[i] = uint16_t(taken);
    }
  }
  return live;
}

void normalise_sums(ImageRGBA& sum, const SampleCounts& counts) {
  for (size_t i = 0; i < counts.size(); ++i) {
    const float inv_samples = 1.0f / float(counts[i]);
    float* p = &sum.pixels[i * 4];
    p[0] *= inv_samples;
    p[1] *= inv_samples;
    p[2] *= inv_samples;
    p[3] = 1.0f;
  }
}

}  // namespace sdfreel
