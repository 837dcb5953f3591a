#include "backends/cpu/covered_pixels.h"

namespace sdfreel {

namespace {

typedef float F4 __attribute__((vector_size(16)));

D4 load4(const double* p) {
  D4 v;
  __builtin_memcpy(&v, p, sizeof v);
  return v;
}

void store4(float* p, D4 v) {
  const F4 f = __builtin_convertvector(v, F4);  // each lane float(double): round to nearest
  __builtin_memcpy(p, &f, sizeof f);
}

}  // namespace

void CoveredPixels::weigh(const TriangleWeights& t) {
  const int end = (count + LANES - 1) / LANES * LANES;
  for (int i = count; i < end; ++i) {
    for (int k = 0; k < 3; ++k) b[k][i] = b[k][0];
    at[i] = at[0];
  }
  for (int i = 0; i < end; i += SPAN) {
    const D4 l[3] = {load4(b[0] + i) / t.area, load4(b[1] + i) / t.area, load4(b[2] + i) / t.area};
    store4(z + i, l[0] * t.depth[0] + l[1] * t.depth[1] + l[2] * t.depth[2]);
    const D4 q[3] = {l[0] * t.inv_w[0], l[1] * t.inv_w[1], l[2] * t.inv_w[2]};
    const D4 sum = q[0] + q[1] + q[2];
    for (int k = 0; k < 3; ++k) store4(w[k] + i, q[k] / sum);
  }
}

}  // namespace sdfreel
