// `sdfreel sheet`: frames spread over the timeline, each the same picture `still` renders at the
// tile's size, labelled, in one PNG; bad options exit 2 and write nothing.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "cli/harness.h"
#include "draw/bitmap_font.h"
#include "draw/canvas.h"
#include "io/png_file.h"

namespace sdfreel::test {
namespace {

namespace fs = std::filesystem;

// The tile at (x0, y0) of the sheet holds the still's pixels, rounded to 8 bits.
void expect_tile_is(const PngPixels& sheet, int x0, int y0, const PngPixels& still) {
  int differing = 0;
  for (int y = 0; y < still.height; ++y)
    for (int x = 0; x < still.width; ++x)
      for (int c = 0; c < 3; ++c) {
        const int want = int(std::lround(still.samples[(y * still.width + x) * 3 + c] / 257.0));
        const int got = sheet.samples[((y0 + y) * sheet.width + x0 + x) * 3 + c] >> 8;
        differing += want != got;
      }
  EXPECT_EQ(differing, 0) << "tile at " << x0 << "," << y0;
}

TEST(Sheet, TilesAreTheFramesSpreadOverTheTimeline) {
  const std::string dir = scratch_dir("sheet");
  write_file(dir + "/t.toml", small_timeline(10));  // 64x36, 10 fps, frames 0-9
  const RunResult r =
      run_sdfreel("sheet t.toml -o s.png --count 3 --columns 2 --tile-width 32", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("wrote s.png: 3 frames (0 to 9) at 32x18"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir + "/out")) << "a sheet writes no render folder";
  const PngPixels sheet = read_png(dir + "/s.png", 3);

  // Frames 0, 5 and 9 (0.0, 0.5 and 0.9 s) as `still` renders them at the same settings.
  const int gap = 8, top = gap + draw::GLYPH_HEIGHT + gap;
  const int cell_w = draw::Canvas::text_width("frame 0  0.00 s");
  const int cell_h = 18 + draw::GLYPH_HEIGHT + 4;
  EXPECT_EQ(sheet.width, gap + 2 * (cell_w + gap));
  EXPECT_EQ(sheet.height, top + 2 * (cell_h + gap));
  const char* times[] = {"0", "0.5", "0.9"};
  for (int i = 0; i < 3; ++i) {
    const std::string still = "f" + std::to_string(i) + ".png";
    ASSERT_EQ(run_sdfreel(std::string("still t.toml --time ") + times[i] + " -o " + still +
                              " --resolution 32x18 --samples 1 --quality draft",
                          dir)
                  .status,
              0);
    expect_tile_is(sheet, gap + (i % 2) * (cell_w + gap), top + (i / 2) * (cell_h + gap),
                   read_png(dir + "/" + still, 3));
  }
}

TEST(Sheet, BadOptionsExit2AndWriteNothing) {
  const std::string dir = scratch_dir("sheet-bad");
  write_file(dir + "/t.toml", small_timeline(4));
  const RunResult ext = run_sdfreel("sheet t.toml -o s.jpg", dir);
  EXPECT_EQ(ext.status, 2);
  EXPECT_NE(ext.err.find("must end in .png"), std::string::npos) << ext.err;
  EXPECT_EQ(run_sdfreel("sheet t.toml -o s.png --count 0", dir).status, 2);
  EXPECT_EQ(run_sdfreel("sheet t.toml -o s.png --frames 7-9", dir).status, 2);
  EXPECT_EQ(run_sdfreel("sheet missing.toml -o s.png", dir).status, 2);
  EXPECT_FALSE(fs::exists(dir + "/s.png"));
  EXPECT_FALSE(fs::exists(dir + "/s.jpg"));
}

}  // namespace
}  // namespace sdfreel::test
