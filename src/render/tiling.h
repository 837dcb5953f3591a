#pragma once
// Runs a function over the image in square tiles on `threads` threads (0 = all cores). Each pixel
// is written by exactly one call, so results never depend on the thread count or tile order.
#include <cstddef>
#include <functional>

namespace sdfreel {

struct Tile {
  int x0, y0, x1, y1;  // half-open pixel rectangle
  int index;           // row-major tile number
};

// Runs fn(i) for every i in [0, n) on `threads` threads (0 = all cores), one index a task (the
// work items differ a lot in cost); in order on the calling thread when threads is 1 or n < 2.
void for_each_index(size_t n, int threads, const std::function<void(size_t)>& fn);

// Runs fn(begin, end) over [0, n) in consecutive ranges of `chunk` items (the last may be shorter)
// on `threads` threads: for passes over a frame's pixels that each pixel does on its own.
void for_each_range(size_t n, size_t chunk, int threads,
                    const std::function<void(size_t begin, size_t end)>& fn);

// Runs fn with `threads` threads for the parallel loops inside it (tbb::parallel_for's included),
// as the loops above: a scene's prepare() that builds its tables in parallel keeps to --threads.
void with_threads(int threads, const std::function<void()>& fn);

int tile_count(int width, int height, int tile_size);
void for_each_tile(int width, int height, int tile_size, int threads,
                   const std::function<void(const Tile&)>& fn);

}  // namespace sdfreel
