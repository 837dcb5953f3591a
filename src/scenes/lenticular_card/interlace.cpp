#include "scenes/lenticular_card/interlace.h"

#include <tbb/parallel_for.h>

#include <cmath>
#include <stdexcept>

namespace sdfreel::lenticular_card {
namespace {

constexpr int MAX_SIDE = 1 << 15;

// Print pixel i (centre i + 0.5) in units of `unit` pixels: the index of the unit it lies in and
// its fraction of the way across. Double: exact enough that every strip keeps its pixels.
void split(int i, double unit, int& index, double& fraction) {
  const double u = (double(i) + 0.5) / unit;
  const double k = std::floor(u);
  index = int(k);
  fraction = u - k;
}

int scaled_size(int n, double scale) {
  return int(std::ceil(double(n) * scale));
}

}  // namespace

InterlaceLayout print_layout(int views, double lpi, double dpi) {
  return InterlaceLayout{views, dpi / lpi, true};
}

std::string layout_problem(const InterlaceLayout& l, int width, int height) {
  if (l.views < 2) return "needs at least 2 views";
  if (!(l.pixels_per_lens >= double(l.views)))
    return "a lens spans " + std::to_string(l.pixels_per_lens) + " print pixels (dpi / lpi), " +
           "fewer than the " + std::to_string(l.views) + " views: raise the dpi or lower the lpi";
  if (width < 1 || height < 1) return "the views are empty";
  const double scale = l.pixels_per_lens;
  if (double(width) * scale >= MAX_SIDE || (l.stretch_rows && double(height) * scale >= MAX_SIDE))
    return "the print would be wider or taller than " + std::to_string(MAX_SIDE) + " pixels";
  return "";
}

int print_width(const InterlaceLayout& l, int view_width) {
  return scaled_size(view_width, l.pixels_per_lens);
}

int print_height(const InterlaceLayout& l, int view_height) {
  return l.stretch_rows ? scaled_size(view_height, l.pixels_per_lens) : view_height;
}

StripSource strip_source(const InterlaceLayout& l, int view_width, int x) {
  int lens = 0;
  double across = 0.0;
  split(x, l.pixels_per_lens, lens, across);
  int strip = int(across * double(l.views));
  if (strip >= l.views) strip = l.views - 1;
  return StripSource{l.views - 1 - strip, lens < view_width ? lens : view_width - 1};
}

int source_row(const InterlaceLayout& l, int view_height, int y) {
  if (!l.stretch_rows) return y;
  int row = 0;
  double unused = 0.0;
  split(y, l.pixels_per_lens, row, unused);
  return row < view_height ? row : view_height - 1;
}

Rgb8Image interlace(const std::vector<Rgb8Image>& views, const InterlaceLayout& l) {
  if (int(views.size()) != l.views)
    throw std::invalid_argument("interlace: " + std::to_string(views.size()) + " views, layout " +
                                "wants " + std::to_string(l.views));
  const int w = views[0].width, h = views[0].height;
  for (const Rgb8Image& v : views)
    if (v.width != w || v.height != h)
      throw std::invalid_argument("interlace: the views differ in size");
  const std::string problem = layout_problem(l, w, h);
  if (!problem.empty()) throw std::invalid_argument("interlace: " + problem);
  Rgb8Image print(print_width(l, w), print_height(l, h));
  std::vector<StripSource> sources(size_t(print.width));
  for (int x = 0; x < print.width; ++x) sources[size_t(x)] = strip_source(l, w, x);
  // Row by row (the print is row-major), rows in parallel: a card's two prints are 5 MB.
  tbb::parallel_for(0, print.height, [&](int y) {
    const int row = source_row(l, h, y);
    uint8_t* to = print.at(0, y);
    for (const StripSource& s : sources) {
      const uint8_t* from = views[s.view].at(s.column, row);
      to[0] = from[0], to[1] = from[1], to[2] = from[2];
      to += 3;
    }
  });
  return print;
}

std::vector<Rgb8Image> deinterlace(const Rgb8Image& print, const InterlaceLayout& l, int w, int h) {
  // Every view pixel is read from the first print pixel that interlace() filled from it: the
  // same mapping both ways, so the round trip is exact whatever the rounding of the layout.
  if (print.width != print_width(l, w) || print.height != print_height(l, h))
    throw std::invalid_argument("deinterlace: the print's size does not match the layout");
  std::vector<Rgb8Image> views(l.views, Rgb8Image(w, h));
  std::vector<int> column_of(size_t(l.views) * w, -1), row_of(h, -1);
  for (int x = print.width - 1; x >= 0; --x) {
    const StripSource s = strip_source(l, w, x);
    column_of[size_t(s.view) * w + s.column] = x;
  }
  for (int y = print.height - 1; y >= 0; --y) row_of[source_row(l, h, y)] = y;
  for (int r = 0; r < h; ++r)
    if (row_of[r] < 0) throw std::invalid_argument("deinterlace: a row is not printed");
  for (int v = 0; v < l.views; ++v)
    for (int c = 0; c < w; ++c) {
      const int x = column_of[size_t(v) * w + c];
      if (x < 0)
        throw std::invalid_argument("deinterlace: view " + std::to_string(v) + " column " +
                                    std::to_string(c) + " is not printed");
      for (int r = 0; r < h; ++r) {
        const uint8_t* from = print.at(x, row_of[r]);
        uint8_t* to = views[v].at(c, r);
        to[0] = from[0], to[1] = from[1], to[2] = from[2];
      }
    }
  return views;
}

}  // namespace sdfreel::lenticular_card
