#include "render/adaptive_sampling.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

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

glm::vec3 display_value(const glm::vec3& mean) {
  return glm::vec3(display_curve(mean.x), display_curve(mean.y), display_curve(mean.z));
}

float own_error(int taken, const glm::vec3& sum, const glm::vec3& sum_odd) {
  if (taken < 2) return 0.0f;
  const float inv_even = 1.0f / float((taken + 1) / 2), inv_odd = 1.0f / float(taken / 2);
  const glm::vec3 even = display_value((sum - sum_odd) * inv_even);
  const glm::vec3 odd = display_value(sum_odd * inv_odd);
  return 0.5f * display_difference(even, odd);
}

float edge_error(int taken, float contrast) {
  return EDGE_WEIGHT * contrast / float(taken);
}

bool needs_more_samples(const AdaptiveSampling& a, int taken, float error) {
  if (taken >= a.maximum) return false;
  if (taken < a.minimum) return true;
  return !(error < a.threshold);
}

std::string adaptive_text(const AdaptiveSampling& a) {
  char b[96];
  std::snprintf(b, sizeof b, "minimum=%d maximum=%d threshold=%.9g", a.minimum, a.maximum,
                double(a.threshold));
  return b;
}

}  // namespace sdfreel
