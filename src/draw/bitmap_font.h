#pragma once
// A small built-in monospaced font for the bench plot and the contact sheet.

namespace sdfreel::draw {

constexpr int GLYPH_WIDTH = 7;    // advance, pixels
constexpr int GLYPH_HEIGHT = 13;  // line height, pixels
constexpr int GLYPH_BASELINE = 10;

// Coverage 0..1 of pixel (x, y) of character c's cell (0 outside the cell or for non-ASCII).
float glyph_coverage(char c, int x, int y);

}  // namespace sdfreel::draw
