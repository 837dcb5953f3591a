#include "draw/contact_sheet.h"

#include <algorithm>
#include <cmath>

#include "draw/bitmap_font.h"

namespace sdfreel::draw {
namespace {

constexpr int kGap = 8;                         // between tiles and around the sheet
constexpr int kLabelHeight = GLYPH_HEIGHT + 4;  // a line of text under each tile
const Rgb kBackground{0.11f, 0.11f, 0.12f}, kText{0.88f, 0.88f, 0.88f};

}  // namespace

std::vector<int> evenly_spaced(const std::vector<int>& frames, int count) {
  const int n = int(frames.size());
  if (count <= 0 || n == 0) return {};
  if (n <= count) return frames;
  if (count == 1) return {frames.front()};
  std::vector<int> out;
  for (int i = 0; i < count; ++i) {
    // i * (n - 1) / (count - 1), rounded, in integers: the same picks on every machine.
    const long long k = (2LL * i * (n - 1) + (count - 1)) / (2LL * (count - 1));
    out.push_back(frames[size_t(k)]);
  }
  return out;  // strictly increasing: n > count makes the step over 1
}

Canvas contact_sheet(const std::vector<SheetTile>& tiles, int columns, const std::string& title) {
  columns = std::max(1, std::min(columns, int(tiles.size())));
  const int rows = (int(tiles.size()) + columns - 1) / columns;
  int cell_w = 0, tile_h = 0;
  for (const SheetTile& t : tiles) {
    cell_w = std::max({cell_w, t.image.width, Canvas::text_width(t.label)});
    tile_h = std::max(tile_h, t.image.height);
  }
  const int cell_h = tile_h + kLabelHeight;
  const int title_h = GLYPH_HEIGHT + kGap;
  const int width =
      std::max(kGap + columns * (cell_w + kGap), 2 * kGap + Canvas::text_width(title));
  Canvas sheet(width, kGap + title_h + rows * (cell_h + kGap), kBackground);
  sheet.text(kGap, kGap, title, kText);
  for (size_t i = 0; i < tiles.size(); ++i) {
    const int x = kGap + int(i % columns) * (cell_w + kGap);
    const int y = kGap + title_h + int(i / columns) * (cell_h + kGap);
    sheet.image(x, y, tiles[i].image);
    sheet.text(x, y + tiles[i].image.height + 2, tiles[i].label, kText);
  }
  return sheet;
}

}  // namespace sdfreel::draw
