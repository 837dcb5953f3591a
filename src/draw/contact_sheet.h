#pragma once
// A contact sheet: frames of a timeline side by side, each labelled, under a title line.
#include <string>
#include <vector>

#include "draw/canvas.h"
#include "render/image.h"

namespace sdfreel::draw {

struct SheetTile {
  ImageRGB16 image;
  std::string label;  // under the image, e.g. "frame 120  5.00 s"
};

// `count` frames spread evenly over `frames` (first and last included, in order, no repeats);
// all of them when there are no more than `count`.
std::vector<int> evenly_spaced(const std::vector<int>& frames, int count);

// Tiles in rows of `columns`, left to right, top to bottom, on a dark background; a column is as
// wide as the widest tile or label.
Canvas contact_sheet(const std::vector<SheetTile>& tiles, int columns, const std::string& title);

}  // namespace sdfreel::draw
