#pragma once
// The least and greatest depth of the sun's map under each 6x6 window of texels the filter reads
// (sun_shadow.h), made once a frame from the drawn map: a point whose reference depth is at most
// its window's least is fully lit (every tap passes), above its window's greatest fully shadowed
// (none does), which are exactly what the filter's loop returns there, 1 and 0, without its 36
// taps. Only penumbrae and windows at the map's border take the loop.
#include <vector>

#include "render/image.h"

namespace sdfreel::museum {

struct SunMapWindows {
  int size = 0;               // the map's texels a side; windows start at 0 .. size - 6
  std::vector<float> lo, hi;  // by window start (x0, y0) with y up, as the filter indexes taps
};

// The windows of `map` (the target SUN_MAP_TARGET: CPU rows top-down, `size` a side).
SunMapWindows sun_map_windows(const ImageRGBA& map, int size);

}  // namespace sdfreel::museum
