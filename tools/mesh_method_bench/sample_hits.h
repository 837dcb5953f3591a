#pragma once
// What each method finds for every sample of a frame: the nearest kept triangle and its depth.
#include <cstdint>
#include <vector>

namespace sdfreel::mesh_bench {

struct SampleHits {
  int width = 0, height = 0, samples = 0;
  std::vector<uint32_t> id;  // triangle id + 1 (FlatTriangles order); 0: nothing drawn
  std::vector<float> depth;  // window depth z_w; 1 where nothing was drawn
  SampleHits(int w, int h, int s)
      : width(w),
        height(h),
        samples(s),
        id(size_t(w) * h * s, 0u),
        depth(size_t(w) * h * s, 1.0f) {}
  size_t index(int sample, int x, int y) const {
    return (size_t(sample) * size_t(height) + size_t(y)) * size_t(width) + size_t(x);
  }
};

}  // namespace sdfreel::mesh_bench
