#include "bench/micro_points.h"

#include <stdexcept>

#include "sdf/lanes.h"

namespace sdfreel::bench {

namespace {

// splitmix64's finaliser: a well-mixed 64-bit value per (seed, index), no generator state.
uint64_t mix(uint64_t z) {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

// Uniform in [0, 1): the top 24 bits, exactly representable as a float.
float unit_float(uint64_t h) {
  return float(h >> 40) * (1.0f / 16777216.0f);
}

}  // namespace

SamplePoints camera_sample_points(const CameraBasis& camera, int width, int height, float max_t,
                                  uint64_t seed) {
  if (width < 1 || height < 1 || (width * height) % LANES != 0)
    throw std::invalid_argument("micro-benchmark view: width * height must be a multiple of 8");
  SamplePoints p;
  const int n = width * height;
  p.x.reserve(n);
  p.y.reserve(n);
  p.z.reserve(n);
  for (int py = 0; py < height; ++py)
    for (int px = 0; px < width; ++px) {
      const uint64_t index = uint64_t(py) * uint64_t(width) + uint64_t(px);
      const float t = max_t * unit_float(mix(seed * 0x9e3779b97f4a7c15ull + index));
      const glm::vec3 dir =
          primary_ray_dir(camera, float(px) + 0.5f, float(py) + 0.5f, width, height);
      const glm::vec3 q = camera.origin + t * dir;
      p.x.push_back(q.x);
      p.y.push_back(q.y);
      p.z.push_back(q.z);
    }
  return p;
}

}  // namespace sdfreel::bench
