#include "render/adaptive_sampling.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace sdfreel {

namespace {

// Plain float arithmetic and a correctly rounded sqrt: the same bits on every build.
float display_curve(float x) {
  const float v = std::max(x, 0.0f);
  return std::sqrt(v / (1.0f + v));
}

}  // namespace

int first_round_samples(const AdaptiveSampling& a) {
  return std::min(a.minimum, a.maximum);
}

int next_round_end(const AdaptiveSampling& a, int taken) {
  return std::min(taken + ADAPTIVE_ROUND, a.maximum);
}

float adaptive_error(int taken, const glm::vec3& sum, const glm::vec3& sum_odd) {
  if (taken < 2) return std::numeric_limits<float>::infinity();
  const float inv_even = 1.0f / float((taken + 1) / 2), inv_odd = 1.0f / float(taken / 2);
  float err = 0.0f;
  for (int c = 0; c < 3; ++c) {
    const float even = (sum[c] - sum_odd[c]) * inv_even, odd = sum_odd[c] * inv_odd;
    err = std::max(err, std::fabs(display_curve(even) - display_curve(odd)));
  }
  return 0.5f * err;
}

bool needs_more_samples(const AdaptiveSampling& a, int taken, const glm::vec3& sum,
                        const glm::vec3& sum_odd) {
  if (taken >= a.maximum) return false;
  if (taken < a.minimum) return true;
  return !(adaptive_error(taken, sum, sum_odd) < a.threshold);
}

std::string adaptive_text(const AdaptiveSampling& a) {
  char b[96];
  std::snprintf(b, sizeof b, "minimum=%d maximum=%d threshold=%.9g", a.minimum, a.maximum,
                double(a.threshold));
  return b;
}

}  // namespace sdfreel
