#include "render/tiling.h"

#include <gtest/gtest.h>
#include <tbb/info.h>
#include <tbb/task_arena.h>

#include <atomic>
#include <vector>

#include "render/sample_pattern.h"

namespace sdfreel {
namespace {

TEST(Tiling, EveryPixelIsVisitedExactlyOnceForAnyThreadCountAndTileSize) {
  for (int threads : {1, 2, 4})
    for (int tile : {1, 7, 16, 64}) {
      const int w = 37, h = 23;
      std::vector<std::atomic<int>> hits(w * h);
      for_each_tile(w, h, tile, threads, [&](const Tile& t) {
        for (int y = t.y0; y < t.y1; ++y)
          for (int x = t.x0; x < t.x1; ++x) hits[y * w + x]++;
      });
      for (auto& v : hits) ASSERT_EQ(v.load(), 1) << threads << " threads, tile " << tile;
    }
}

TEST(SamplePattern, OneSampleIsThePixelCentreAndManyAreDistinctInTheUnitSquare) {
  ASSERT_EQ(sample_offsets(1).size(), 1u);
  EXPECT_EQ(sample_offsets(1)[0], glm::vec2(0.5f));
  const auto s = sample_offsets(16);
  ASSERT_EQ(s.size(), 16u);
  glm::vec2 mean(0.0f);
  for (size_t i = 0; i < s.size(); ++i) {
    EXPECT_GE(s[i].x, 0.0f);
    EXPECT_LT(s[i].x, 1.0f);
    EXPECT_GE(s[i].y, 0.0f);
    EXPECT_LT(s[i].y, 1.0f);
    for (size_t j = 0; j < i; ++j) EXPECT_NE(s[i], s[j]);
    mean += s[i];
  }
  mean /= 16.0f;  // low discrepancy: the mean sits near the pixel centre
  EXPECT_NEAR(mean.x, 0.5f, 0.04f);
  EXPECT_NEAR(mean.y, 0.5f, 0.04f);
  EXPECT_EQ(sample_offsets(16), s);  // fixed
}

// with_threads bounds the parallel loops inside it, a scene's own tbb::parallel_for included.
TEST(Tiling, WithThreadsBoundsTheLoopsInside) {
  for (int threads : {1, 2, 3}) {
    int seen = 0;
    with_threads(threads, [&] { seen = tbb::this_task_arena::max_concurrency(); });
    EXPECT_EQ(seen, threads);
  }
  int all = 0;
  with_threads(0, [&] { all = tbb::this_task_arena::max_concurrency(); });
  EXPECT_EQ(all, tbb::info::default_concurrency());
}

}  // namespace
}  // namespace sdfreel
