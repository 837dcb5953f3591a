#include "bench/micro_check.h"

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <vector>

namespace sdfreel::bench {

namespace {

uint32_t bits(float f) {
  uint32_t u;
  std::memcpy(&u, &f, sizeof u);
  return u;
}

}  // namespace

std::optional<LaneMismatch> first_lane_mismatch(const DistanceFunction& fn,
                                                const SamplePoints& points) {
  const int n = points.size();
  // Filled with different patterns so that a lane left unwritten by either path is caught.
  std::vector<float> scalar(n, 1.0f), lanes(n, -1.0f);
  fn.scalar(points.x.data(), points.y.data(), points.z.data(), scalar.data(), n);
  fn.lanes(points.x.data(), points.y.data(), points.z.data(), lanes.data(), n);
  for (int i = 0; i < n; ++i)
    if (bits(scalar[i]) != bits(lanes[i]))
      return LaneMismatch{i, points.x[i], points.y[i], points.z[i], scalar[i], lanes[i]};
  return std::nullopt;
}

std::string describe(const std::string& scene, const std::string& function, const LaneMismatch& m) {
  char buf[320];
  std::snprintf(buf, sizeof buf,
                "%s/%s: lanes differ from scalar at point %d (%.9g, %.9g, %.9g): scalar %.9g "
                "(0x%08x), lanes %.9g (0x%08x)",
                scene.c_str(), function.c_str(), m.index, double(m.x), double(m.y), double(m.z),
                double(m.scalar), unsigned(bits(m.scalar)), double(m.lanes),
                unsigned(bits(m.lanes)));
  return buf;
}

}  // namespace sdfreel::bench
