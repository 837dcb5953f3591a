#include "render/live_pixels.h"

#include <algorithm>
#include <atomic>

#include "render/tiling.h"

namespace sdfreel {

namespace {

constexpr size_t ROWS_A_TASK = 16;
constexpr size_t PIXELS_A_TASK = 1 << 14;

glm::vec3 rgb(const float* p) {
  return glm::vec3(p[0], p[1], p[2]);
}

}  // namespace

LivePixels::LivePixels(const AdaptiveSampling& a, int width, int height, int threads)
    : a_(a),
      width_(width),
      height_(height),
      threads_(threads),
      next_end_(first_round_samples(a)),
      live_(size_t(width) * height, 1),
      taken_(size_t(width) * height, uint16_t(a.maximum)) {}

bool LivePixels::round_ends_at(int taken) const {
  return taken == next_end_ && taken < a_.maximum;
}

float LivePixels::contrast(int x, int y) const {
  const glm::vec3& centre = display_[size_t(y) * width_ + x];
  float c = 0.0f;
  for (int j = std::max(y - 1, 0); j <= std::min(y + 1, height_ - 1); ++j)
    for (int i = std::max(x - 1, 0); i <= std::min(x + 1, width_ - 1); ++i)
      c = std::max(c, display_difference(centre, display_[size_t(j) * width_ + i]));
  return c;
}

int LivePixels::decide(int taken, const ImageRGBA& sum, const ImageRGBA& sum_odd) {
  next_end_ = next_round_end(a_, taken);
  const float inv_taken = 1.0f / float(taken);
  const size_t width = size_t(width_);
  display_.resize(live_.size());  // at the first decision: fixed sampling never needs it
  for_each_range(size_t(height_), ROWS_A_TASK, threads_, [&](size_t y0, size_t y1) {
    for (size_t i = y0 * width; i < y1 * width; ++i)
      if (live_[i]) display_[i] = display_value(rgb(&sum.pixels[i * 4]) * inv_taken);
  });
  // Decisions read only the display values of finished rounds, never which pixels stopped in
  // this pass: the rows decide on their own.
  std::atomic<int> live{0};
  for_each_range(size_t(height_), ROWS_A_TASK, threads_, [&](size_t y0, size_t y1) {
    int live_here = 0;
    for (int y = int(y0); y < int(y1); ++y)
      for (int x = 0; x < width_; ++x) {
        const size_t i = size_t(y) * width + x;
        if (!live_[i]) continue;
        const float error =
            std::max(own_error(taken, rgb(&sum.pixels[i * 4]), rgb(&sum_odd.pixels[i * 4])),
                     edge_error(taken, contrast(x, y)));
        if (needs_more_samples(a_, taken, error)) {
          ++live_here;
        } else {
          live_[i] = 0;
          taken_[i] = uint16_t(taken);
        }
      }
    live += live_here;
  });
  all_live_ = all_live_ && size_t(live.load()) == live_.size();
  return live;
}

void normalise_sums(ImageRGBA& sum, const SampleCounts& counts, int threads) {
  for_each_range(counts.size(), PIXELS_A_TASK, threads, [&](size_t begin, size_t end) {
    for (size_t i = begin; i < end; ++i) {
      const float inv_samples = 1.0f / float(counts[i]);
      float* p = &sum.pixels[i * 4];
      p[0] *= inv_samples;
      p[1] *= inv_samples;
      p[2] *= inv_samples;
      p[3] = 1.0f;
    }
  });
}

}  // namespace sdfreel
