#include "render/tiling.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

namespace sdfreel {

int tile_count(int width, int height, int tile_size) {
  return ((width + tile_size - 1) / tile_size) * ((height + tile_size - 1) / tile_size);
}

void for_each_tile(int width, int height, int tile_size, int threads,
                   const std::function<void(const Tile&)>& fn) {
  const int tiles_x = (width + tile_size - 1) / tile_size;
  const int n = tile_count(width, height, tile_size);
  auto run_one = [&](int i) {
    const int tx = i % tiles_x, ty = i / tiles_x;
    Tile t{tx * tile_size, ty * tile_size, 0, 0, i};
    t.x1 = std::min(width, t.x0 + tile_size);
    t.y1 = std::min(height, t.y0 + tile_size);
    fn(t);
  };
  if (threads == 1) {
    for (int i = 0; i < n; ++i) run_one(i);
    return;
  }
  // Dynamic scheduling (grain 1): tiles differ a lot in cost (sky vs. object).
  tbb::task_arena arena(threads > 0 ? threads : tbb::task_arena::automatic);
  arena.execute([&] {
    tbb::parallel_for(
        tbb::blocked_range<int>(0, n, 1),
        [&](const tbb::blocked_range<int>& r) {
          for (int i = r.begin(); i != r.end(); ++i) run_one(i);
        },
        tbb::simple_partitioner());
  });
}

}  // namespace sdfreel
