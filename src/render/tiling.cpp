#include "render/tiling.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>

namespace sdfreel {

int tile_count(int width, int height, int tile_size) {
  return ((width + tile_size - 1) / tile_size) * ((height + tile_size - 1) / tile_size);
}

void with_threads(int threads, const std::function<void()>& fn) {
  tbb::task_arena arena(threads > 0 ? threads : tbb::task_arena::automatic);
  arena.execute(fn);
}

void for_each_index(size_t n, int threads, const std::function<void(size_t)>& fn) {
  if (threads == 1 || n < 2) {  // no arena for a single item
    for (size_t i = 0; i < n; ++i) fn(i);
    return;
  }
  with_threads(threads, [&] {
    tbb::parallel_for(
        tbb::blocked_range<size_t>(0, n, 1),
        [&](const tbb::blocked_range<size_t>& r) {
          for (size_t i = r.begin(); i != r.end(); ++i) fn(i);
        },
        tbb::simple_partitioner());
  });
}

void for_each_range(size_t n, size_t chunk, int threads,
                    const std::function<void(size_t begin, size_t end)>& fn) {
  for_each_index((n + chunk - 1) / chunk, threads,
                 [&](size_t k) { fn(k * chunk, std::min(n, (k + 1) * chunk)); });
}

void for_each_tile(int width, int height, int tile_size, int threads,
                   const std::function<void(const Tile&)>& fn) {
  const int tiles_x = (width + tile_size - 1) / tile_size;
  for_each_index(size_t(tile_count(width, height, tile_size)), threads, [&](size_t index) {
    const int i = int(index), tx = i % tiles_x, ty = i / tiles_x;
    Tile t{tx * tile_size, ty * tile_size, 0, 0, i};
    t.x1 = std::min(width, t.x0 + tile_size);
    t.y1 = std::min(height, t.y0 + tile_size);
    fn(t);
  });
}

}  // namespace sdfreel
