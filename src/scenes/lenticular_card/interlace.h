#pragma once
// Interlacing (seed 004, exhibit 2, step 2): N views cut into strips, one strip of every view
// under each lens of a lenticular sheet, as a real card is printed. Pure functions of the views
// and the layout, shared by `sdfreel interlace` (a printable image) and the lenticular_card scene
// (the print under its sheet).
//
// Layout: one lens per view column, so a W-column view makes a print W lenses wide. A lens spans
// p = dpi / lpi print pixels; print column x (centre x + 0.5) lies under lens k = floor(u) with
// u = (x + 0.5) / p, at strip floor(fract(u) * N), which shows view N - 1 - strip (the lens
// inverts: the leftmost strip is seen from the right). With stretch_rows, rows are scaled by p
// too, so the printed card keeps the views' aspect; without, print row y is view row y.
#include <cstdint>
#include <string>
#include <vector>

namespace sdfreel::lenticular_card {

struct Rgb8Image {
  int width = 0, height = 0;
  std::vector<uint8_t> rgb;  // 3 bytes a pixel, row-major, top row first
  Rgb8Image() = default;
  Rgb8Image(int w, int h) : width(w), height(h), rgb(size_t(w) * h * 3, 0) {}
  uint8_t* at(int x, int y) { return &rgb[(size_t(y) * width + x) * 3]; }
  const uint8_t* at(int x, int y) const { return &rgb[(size_t(y) * width + x) * 3]; }
};

struct InterlaceLayout {
  int views = 16;
  double pixels_per_lens = 16.0;  // print dpi / lens lpi
  bool stretch_rows = true;
};

// The layout for a print at `dpi` under a sheet of `lpi` lenses per inch.
InterlaceLayout print_layout(int views, double lpi, double dpi);

// "" when the layout can interlace views of width x height, else why not (each strip needs at
// least one print pixel: pixels_per_lens >= views; sizes must stay below 2^15 a side).
std::string layout_problem(const InterlaceLayout& layout, int width, int height);

// Size of the print for views of width x height.
int print_width(const InterlaceLayout& layout, int view_width);
int print_height(const InterlaceLayout& layout, int view_height);

// Which view and which of its columns print column x shows.
struct StripSource {
  int view, column;
};
StripSource strip_source(const InterlaceLayout& layout, int view_width, int x);
// The view row that print row y shows.
int source_row(const InterlaceLayout& layout, int view_height, int y);

// The interlaced print. Throws std::invalid_argument when views differ in size, their number is
// not layout.views, or layout_problem() names a problem.
Rgb8Image interlace(const std::vector<Rgb8Image>& views, const InterlaceLayout& layout);

// The views back from a print (the inverse of interlace for the same layout and view size).
std::vector<Rgb8Image> deinterlace(const Rgb8Image& print, const InterlaceLayout& layout,
                                   int view_width, int view_height);

}  // namespace sdfreel::lenticular_card
