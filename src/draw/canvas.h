#pragma once
// A small RGB raster for the bench plot and the contact sheet: images, anti-aliased lines and
// discs, text in the built-in font.
#include <string>
#include <vector>

#include "render/image.h"

namespace sdfreel::draw {

struct Rgb {
  float r, g, b;
};

class Canvas {
 public:
  Canvas(int width, int height, Rgb background);
  int width() const { return w_; }
  int height() const { return h_; }
  Rgb at(int x, int y) const;
  // Blends colour c over pixel (x, y) with coverage a (0..1); outside the canvas: nothing.
  void blend(int x, int y, Rgb c, float a);
  void fill_rect(int x0, int y0, int x1, int y1, Rgb c);  // [x0, x1) x [y0, y1)
  // Copies display pixels with their top-left corner at (x, y), clipped to the canvas.
  void image(int x, int y, const ImageRGB16& img);
  void line(float x0, float y0, float x1, float y1, float width, Rgb c);
  void disc(float cx, float cy, float radius, Rgb c);
  void ring(float cx, float cy, float radius, float width, Rgb c);
  // Text with its top-left corner at (x, y), or rotated a quarter turn counter-clockwise (reading
  // upwards) when `vertical`. Returns the text's advance in pixels.
  int text(int x, int y, const std::string& s, Rgb c, bool vertical = false);
  static int text_width(const std::string& s);
  // 8-bit sRGB-ish PNG (the colours are display values already) through libpng.
  void write_png(const std::string& path) const;

 private:
  int w_, h_;
  std::vector<float> px_;  // 3 floats per pixel
};

}  // namespace sdfreel::draw
