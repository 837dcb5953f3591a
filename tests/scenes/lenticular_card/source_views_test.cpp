// Source views are deterministic, made once: the first call renders and stores each view under
// the cache folder by its content key, later calls read the stored bytes; a different camera or
// size is a different key.
#include "scenes/lenticular_card/source_views.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

#include "io/cache_file.h"
#include "support/scratch.h"

namespace sdfreel::lenticular_card {
namespace {

namespace fs = std::filesystem;

TEST(SourceViews, RenderedOnceThenReadFromTheCacheByContentKey) {
  const std::string dir = test::scratch_dir("lenticular_views");
  ::setenv("SDFREEL_CACHE_DIR", dir.c_str(), 1);
  const ViewSet set{"sdf_morph", 3, 12, 9, 1, 0.5, 20.0, 1.0};
  const std::vector<Rgb8Image> first = source_views(set);
  ASSERT_EQ(first.size(), 3u);
  EXPECT_EQ(first[1].rgb, render_view(set, 1).rgb) << "a view is a pure function of its key";
  EXPECT_NE(first[0].rgb, first[2].rgb) << "the views see the scene from different angles";
  const fs::path stored = cache_file_path("lenticular", view_key(set, 1));
  ASSERT_TRUE(fs::exists(stored));
  // A stored file stands for its view: replace it and the next call returns the replacement.
  Rgb8Image marked = first[1];
  marked.rgb[0] ^= 0xff;
  ASSERT_TRUE(write_cache_file("lenticular", view_key(set, 1),
                               std::vector<char>(marked.rgb.begin(), marked.rgb.end())));
  EXPECT_EQ(source_views(set)[1].rgb, marked.rgb);
  // A damaged file is not trusted: the view is rendered again.
  test::write_file(stored.string(), "not a cache file");
  EXPECT_EQ(source_views(set)[1].rgb, first[1].rgb);
  ViewSet other = set;
  other.orbit_deg = 21.0;  // moves every view but the middle one
  EXPECT_NE(view_key(other, 0), view_key(set, 0));
  EXPECT_EQ(view_key(other, 1), view_key(set, 1));
  other = set;
  other.width = 13;
  EXPECT_NE(view_key(other, 1), view_key(set, 1));
}

}  // namespace
}  // namespace sdfreel::lenticular_card
