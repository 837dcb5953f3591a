#pragma once
// Runs a function over the image in square tiles on `threads` threads (0 = all cores). Each pixel
// is written by exactly one call, so results never depend on the thread count or tile order.
#include <functional>

namespace sdfreel {

struct Tile {
  int x0, y0, x1, y1;  // half-open pixel rectangle
  int index;           // row-major tile number
};

int tile_count(int width, int height, int tile_size);
void for_each_tile(int width, int height, int tile_size, int threads,
                   const std::function<void(const Tile&)>& fn);

}  // namespace sdfreel
