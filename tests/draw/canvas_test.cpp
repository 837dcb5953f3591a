// The raster the bench plot and the contact sheet draw on.
#include "draw/canvas.h"

#include <gtest/gtest.h>

namespace sdfreel::draw {
namespace {

TEST(Canvas, TextDrawsGlyphs) {
  Canvas c(40, 20, Rgb{1, 1, 1});
  EXPECT_EQ(c.text(2, 2, "A1", Rgb{0, 0, 0}), 2 * Canvas::text_width("A"));
  int inked = 0;
  for (int y = 0; y < 20; ++y)
    for (int x = 0; x < 40; ++x) inked += c.at(x, y).r < 0.5f;
  EXPECT_GT(inked, 10);
  Canvas blank(40, 20, Rgb{1, 1, 1});
  blank.text(2, 2, "  ", Rgb{0, 0, 0});
  for (int y = 0; y < 20; ++y)
    for (int x = 0; x < 40; ++x) EXPECT_EQ(blank.at(x, y).r, 1.0f);
}

TEST(Canvas, ImageCopiesDisplayPixelsAndClipsAtTheEdges) {
  ImageRGB16 img(3, 2);
  for (size_t i = 0; i < img.pixels.size(); ++i) img.pixels[i] = uint16_t(i * 3000);
  Canvas c(4, 4, Rgb{0.5f, 0.5f, 0.5f});
  c.image(2, -1, img);  // only columns 0-1 of its second row land on the canvas
  EXPECT_FLOAT_EQ(c.at(2, 0).r, float(9 * 3000) / 65535.0f);
  EXPECT_FLOAT_EQ(c.at(3, 0).b, float(14 * 3000) / 65535.0f);
  EXPECT_EQ(c.at(1, 0).r, 0.5f);
  EXPECT_EQ(c.at(2, 1).r, 0.5f);
  Canvas whole(3, 2, Rgb{0, 0, 0});
  whole.image(0, 0, img);
  EXPECT_FLOAT_EQ(whole.at(0, 0).g, 3000.0f / 65535.0f);
  EXPECT_FLOAT_EQ(whole.at(2, 1).b, float(17 * 3000) / 65535.0f);
}

}  // namespace
}  // namespace sdfreel::draw
