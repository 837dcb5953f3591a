#include "render/sample_pattern.h"

namespace sdfreel {

std::vector<glm::vec2> sample_offsets(int n) {
  std::vector<glm::vec2> out;
  if (n <= 1) return {glm::vec2(0.5f)};
  // Plastic-number constants of R2; computed in double and rounded once, so exact and portable.
  const double g = 1.32471795724474602596;
  const double a1 = 1.0 / g, a2 = 1.0 / (g * g);
  for (int i = 0; i < n; ++i) {
    double x = 0.5 + a1 * i, y = 0.5 + a2 * i;
    x -= double(long(x));
    y -= double(long(y));
    out.emplace_back(float(x), float(y));
  }
  return out;
}

}  // namespace sdfreel
