#include "render/sample_pattern.h"

namespace sdfreel {

namespace {

double wrap01(double x) {
  return x - double(long(x < 0.0 ? x - 1.0 : x));
}

}  // namespace

std::vector<glm::vec2> sample_offsets(int n) {
  if (n <= 1) return {glm::vec2(0.5f)};
  // R2's plastic-number steps, computed in double and rounded once, so exact and portable.
  const double g = 1.32471795724474602596;
  const double a1 = 1.0 / g, a2 = 1.0 / (g * g);
  std::vector<double> xs(n), ys(n);
  double mx = 0.0, my = 0.0;
  for (int i = 0; i < n; ++i) {
    xs[i] = wrap01(0.5 + a1 * i);
    ys[i] = wrap01(0.5 + a2 * i);
    mx += xs[i];
    my += ys[i];
  }
  // A few R2 points are biased towards one corner (mean 0.38 for n = 2..4), which would shift the
  // image by a tenth of a pixel. Shifting the set on the torus centres it without changing its
  // spacing.
  mx /= n;
  my /= n;
  std::vector<glm::vec2> out;
  for (int i = 0; i < n; ++i)
    out.emplace_back(float(wrap01(xs[i] + 0.5 - mx)), float(wrap01(ys[i] + 0.5 - my)));
  return out;
}

}  // namespace sdfreel
