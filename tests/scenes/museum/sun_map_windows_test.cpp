// The sun map's windows (sun_map_windows.h): each is its 6x6 texels' least and greatest depth, and
// the filter with them returns exactly what it returns without them, at lit, shadowed and penumbra
// points, in the map's middle and at its borders.
#include "scenes/museum/sun_map_windows.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <random>

#include "scenes/museum/sun_shadow.h"

namespace sdfreel::museum {
namespace {

// A map of blocks of random depth, `block` texels a side, with a few single-texel specks.
ImageRGBA blocky_map(int size, int block, std::mt19937& rng) {
  std::uniform_real_distribution<float> depth(0.3f, 0.7f);
  ImageRGBA map(size, size);
  std::vector<float> blocks(size_t((size / block + 1) * (size / block + 1)));
  for (float& d : blocks) d = depth(rng);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x)
      map.at(x, y)[0] = blocks[size_t((y / block) * (size / block + 1) + x / block)];
  std::uniform_int_distribution<int> at(0, size - 1);
  for (int i = 0; i < size; ++i) map.at(at(rng), at(rng))[0] = depth(rng);
  return map;
}

TEST(SunMapWindows, EachWindowIsItsTexelsLeastAndGreatest) {
  std::mt19937 rng(3);
  const int size = 23;
  const ImageRGBA map = blocky_map(size, 3, rng);
  const SunMapWindows w = sun_map_windows(map, size);
  const int n = size - SUN_MAP_FILTER_TAPS + 1;
  ASSERT_EQ(w.lo.size(), size_t(n * n));
  for (int y0 = 0; y0 < n; ++y0)
    for (int x0 = 0; x0 < n; ++x0) {
      float lo = 2.0f, hi = -1.0f;
      for (int j = 0; j < SUN_MAP_FILTER_TAPS; ++j)
        for (int i = 0; i < SUN_MAP_FILTER_TAPS; ++i) {
          const float d = map.at(x0 + i, size - 1 - (y0 + j))[0];  // rows top-down, y up
          lo = std::min(lo, d), hi = std::max(hi, d);
        }
      EXPECT_EQ(w.lo[size_t(y0 * n + x0)], lo) << x0 << ", " << y0;
      EXPECT_EQ(w.hi[size_t(y0 * n + x0)], hi) << x0 << ", " << y0;
    }
}

TEST(SunMapWindows, TheFilterGivesTheSameBitsWithThem) {
  std::mt19937 rng(5);
  const SunView& s = sun_view();
  const ImageRGBA map = blocky_map(s.size, 7, rng);
  const SunMapWindows windows = sun_map_windows(map, s.size);
  std::uniform_real_distribution<float> texel(-8.0f, float(s.size) + 8.0f), ref(0.25f, 0.75f),
      ndl(0.05f, 1.0f);
  int lit = 0, shadowed = 0, penumbra = 0;
  for (int i = 0; i < 200000; ++i) {
    const float u = s.u0 + texel(rng) * s.texel, v = s.v0 + texel(rng) * s.texel;
    const float w = s.near_plane + ref(rng) / s.inv_depth_range;
    const glm::vec3 p = s.origin + s.right * u + s.up * v + s.forward * w;
    const float n = ndl(rng);
    const float plain = sun_map_visibility(map, s, p, n);
    const float fast = sun_map_visibility(map, s, p, n, &windows);
    ASSERT_EQ(0, std::memcmp(&plain, &fast, sizeof plain)) << "point " << i;
    lit += plain == 1.0f, shadowed += plain == 0.0f, penumbra += plain > 0.0f && plain < 1.0f;
  }
  // Every kind of point was met many times (the windows' two answers and the loop's).
  EXPECT_GT(lit, 10000);
  EXPECT_GT(shadowed, 10000);
  EXPECT_GT(penumbra, 10000);
}

}  // namespace
}  // namespace sdfreel::museum
