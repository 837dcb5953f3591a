// The contact sheet's choice of frames and its layout.
#include "draw/contact_sheet.h"

#include <gtest/gtest.h>

#include "draw/bitmap_font.h"
#include "support/solid_image.h"

namespace sdfreel::draw {
namespace {

std::vector<int> range(int n) {
  std::vector<int> v;
  for (int i = 0; i < n; ++i) v.push_back(i);
  return v;
}

TEST(EvenlySpaced, TakesFirstAndLastAndSpreadsTheRest) {
  EXPECT_EQ(evenly_spaced(range(360), 4), (std::vector<int>{0, 120, 239, 359}));
  EXPECT_EQ(evenly_spaced(range(10), 3), (std::vector<int>{0, 5, 9}));  // 4.5 rounds up
  EXPECT_EQ(evenly_spaced(range(5), 1), (std::vector<int>{0}));
  EXPECT_EQ(evenly_spaced({3, 4, 7}, 12), (std::vector<int>{3, 4, 7}));  // fewer than asked: all
  EXPECT_TRUE(evenly_spaced({}, 4).empty());
  const std::vector<int> picks = evenly_spaced(range(13), 12);
  ASSERT_EQ(picks.size(), 12u);
  for (size_t i = 1; i < picks.size(); ++i) EXPECT_LT(picks[i - 1], picks[i]);
  EXPECT_EQ(picks.back(), 12);
}

// Three 120x20 tiles in rows of two: red and green on the first row, blue under red, each with
// its label inked just below it.
TEST(ContactSheet, PlacesTilesInRowsWithTheirLabels) {
  const std::vector<SheetTile> tiles = {{test::solid_frame(120, 20, 65535, 0, 0), "one"},
                                        {test::solid_frame(120, 20, 0, 65535, 0), "two"},
                                        {test::solid_frame(120, 20, 0, 0, 65535), "three"}};
  const Canvas sheet = contact_sheet(tiles, 2, "title");
  const int gap = 8, top = gap + GLYPH_HEIGHT + gap, cell_h = 20 + GLYPH_HEIGHT + 4;
  EXPECT_EQ(sheet.width(), gap + 2 * (120 + gap));
  EXPECT_EQ(sheet.height(), top + 2 * (cell_h + gap));
  EXPECT_EQ(sheet.at(gap, top).r, 1.0f);
  EXPECT_EQ(sheet.at(gap + 119, top + 19).r, 1.0f);
  EXPECT_EQ(sheet.at(gap + 120 + gap, top).g, 1.0f);
  EXPECT_EQ(sheet.at(gap, top + cell_h + gap).b, 1.0f);
  EXPECT_LT(sheet.at(gap + 120, top).r, 0.5f) << "background between the tiles";
  auto inked = [&](int x0, int y0, int w, int h) {
    int n = 0;
    for (int y = y0; y < y0 + h; ++y)
      for (int x = x0; x < x0 + w; ++x) n += sheet.at(x, y).r > 0.5f;
    return n;
  };
  EXPECT_GT(inked(gap, top + 20, 40, GLYPH_HEIGHT + 4), 10) << "label under the first tile";
  EXPECT_GT(inked(gap, gap, 40, GLYPH_HEIGHT), 10) << "the title";
  EXPECT_EQ(inked(gap + 120 + gap, top + cell_h + gap, 120, cell_h), 0) << "no fourth tile";
}

TEST(ContactSheet, AColumnIsAsWideAsItsLongestLabel) {
  const std::string label = "frame 120  5.00 s";
  const Canvas sheet = contact_sheet({{test::solid_frame(16, 9, 0, 0, 0), label}}, 4, "t");
  EXPECT_EQ(sheet.width(), 8 + Canvas::text_width(label) + 8);
}

}  // namespace
}  // namespace sdfreel::draw
