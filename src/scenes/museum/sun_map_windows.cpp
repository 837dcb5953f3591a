#include "scenes/museum/sun_map_windows.h"

#include "scenes/museum/sun_shadow.h"
#include "sdf/det_math.h"

namespace sdfreel::museum {

SunMapWindows sun_map_windows(const ImageRGBA& map, int size) {
  constexpr int TAPS = SUN_MAP_FILTER_TAPS;
  const int n = size - TAPS + 1;  // window starts a side
  SunMapWindows w;
  w.size = size;
  if (n <= 0) return w;
  // Along x first (rows of size x n), then along y: a window's extremes are its rows' extremes.
  std::vector<float> row_lo(size_t(size) * n), row_hi(size_t(size) * n);
  for (int y = 0; y < size; ++y)
    for (int x0 = 0; x0 < n; ++x0) {
      float lo = map.at(x0, size - 1 - y)[0], hi = lo;
      for (int i = 1; i < TAPS; ++i) {
        const float d = map.at(x0 + i, size - 1 - y)[0];
        lo = dm::min(lo, d), hi = dm::max(hi, d);
      }
      row_lo[size_t(y) * n + x0] = lo, row_hi[size_t(y) * n + x0] = hi;
    }
  w.lo.resize(size_t(n) * n);
  w.hi.resize(size_t(n) * n);
  for (int y0 = 0; y0 < n; ++y0)
    for (int x0 = 0; x0 < n; ++x0) {
      float lo = row_lo[size_t(y0) * n + x0], hi = row_hi[size_t(y0) * n + x0];
      for (int j = 1; j < TAPS; ++j) {
        lo = dm::min(lo, row_lo[size_t(y0 + j) * n + x0]);
        hi = dm::max(hi, row_hi[size_t(y0 + j) * n + x0]);
      }
      w.lo[size_t(y0) * n + x0] = lo, w.hi[size_t(y0) * n + x0] = hi;
    }
  return w;
}

}  // namespace sdfreel::museum
