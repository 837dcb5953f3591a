// Interlacing then de-interlacing gives back every view exactly, for whole and fractional print
// pixels per lens, with and without stretched rows; and the strips lie where the layout says.
#include "scenes/lenticular_card/interlace.h"

#include <gtest/gtest.h>

namespace sdfreel::lenticular_card {
namespace {

// Views whose every pixel is distinct: view index, column and row in the three channels.
std::vector<Rgb8Image> numbered_views(int n, int w, int h) {
  std::vector<Rgb8Image> views;
  for (int v = 0; v < n; ++v) {
    Rgb8Image img(w, h);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        uint8_t* p = img.at(x, y);
        p[0] = uint8_t(v), p[1] = uint8_t(x), p[2] = uint8_t(y);
      }
    views.push_back(img);
  }
  return views;
}

void expect_round_trip(const InterlaceLayout& layout, int w, int h) {
  const std::vector<Rgb8Image> views = numbered_views(layout.views, w, h);
  const Rgb8Image print = interlace(views, layout);
  const std::vector<Rgb8Image> back = deinterlace(print, layout, w, h);
  ASSERT_EQ(back.size(), views.size());
  for (size_t v = 0; v < views.size(); ++v)
    EXPECT_EQ(back[v].rgb, views[v].rgb)
        << "view " << v << ", " << layout.pixels_per_lens << " pixels per lens";
}

TEST(Interlace, RoundTripGivesBackEveryView) {
  expect_round_trip(InterlaceLayout{16, 16.0, false}, 192, 144);  // the scene's print
  expect_round_trip(print_layout(16, 40.0, 720.0), 20, 12);       // 18 pixels a lens
  expect_round_trip(print_layout(9, 62.0, 600.0), 31, 7);         // 9.677...: strips of 1 or 2
  expect_round_trip(print_layout(2, 75.0, 150.0), 5, 3);          // exactly one pixel a strip
  expect_round_trip(print_layout(7, 3.0, 100.0), 4, 4);           // 33.3 pixels a lens
}

TEST(Interlace, EveryViewAppearsUnderEveryLensInReverseOrder) {
  const InterlaceLayout layout{4, 4.0, false};
  const Rgb8Image print = interlace(numbered_views(4, 3, 1), layout);
  ASSERT_EQ(print.width, 12);
  for (int x = 0; x < 12; ++x) {
    EXPECT_EQ(print.at(x, 0)[0], 3 - x % 4) << "x " << x;  // the lens inverts
    EXPECT_EQ(print.at(x, 0)[1], x / 4) << "x " << x;      // one lens a view column
  }
}

TEST(Interlace, StretchedRowsKeepTheAspect) {
  const InterlaceLayout layout = print_layout(4, 50.0, 300.0);  // 6 pixels a lens
  EXPECT_EQ(print_width(layout, 10), 60);
  EXPECT_EQ(print_height(layout, 5), 30);
}

TEST(Interlace, RefusesTooFewPixelsPerLensAndMismatchedViews) {
  EXPECT_NE(layout_problem(print_layout(16, 60.0, 600.0), 8, 8), "");  // 10 pixels, 16 views
  EXPECT_EQ(layout_problem(print_layout(10, 60.0, 600.0), 8, 8), "");
  EXPECT_NE(layout_problem(print_layout(1, 60.0, 600.0), 8, 8), "");
  std::vector<Rgb8Image> views = numbered_views(3, 4, 4);
  views[1] = Rgb8Image(5, 4);
  EXPECT_THROW(interlace(views, print_layout(3, 10.0, 100.0)), std::invalid_argument);
  EXPECT_THROW(interlace(numbered_views(2, 4, 4), print_layout(3, 10.0, 100.0)),
               std::invalid_argument);
}

}  // namespace
}  // namespace sdfreel::lenticular_card
