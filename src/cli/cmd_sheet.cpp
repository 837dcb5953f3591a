// `sdfreel sheet TIMELINE -o sheet.png`: a contact sheet, N frames spread over the timeline, small
// and labelled, for a look at a whole flythrough in seconds.
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "cli/commands_impl.h"
#include "cli/quick_look_options.h"
#include "draw/contact_sheet.h"

namespace sdfreel {

namespace {

struct SheetOptions {
  RenderOptions render;
  std::string output;
  int count = 12;
  int columns = 4;
  int tile_width = 320;
};

std::string label_of(int frame, double fps) {
  char s[64];
  std::snprintf(s, sizeof s, "frame %d  %.2f s", frame, double(frame) / fps);
  return s;
}

int run_sheet(const SheetOptions& o) {
  if (std::filesystem::path(o.output).extension() != ".png")
    throw UsageError("-o " + o.output + ": the contact sheet is a PNG, the file must end in .png");
  RenderOptions ro = o.render;
  ro.no_video = true;  // tiles are never encoded, so h264's even-size rule does not apply
  Timeline tl = load_with_overrides(ro);
  apply_quick_look(ro, tl);  // and the tile's size:
  const double aspect = double(tl.height) / double(tl.width);
  tl.width = o.tile_width;
  tl.height = std::max(2, int(std::lround(o.tile_width * aspect)));

  const std::vector<int> frames = draw::evenly_spaced(selected_frames(tl, ro), o.count);
  const auto start = std::chrono::steady_clock::now();
  FramePipeline pipe(tl, timeline_backend(tl, ro));
  std::vector<draw::SheetTile> tiles;
  const bool tty = ::isatty(STDERR_FILENO);  // a count that rewrites itself only on a terminal
  for (int frame : frames) {
    tiles.push_back({pipe.render(frame).display, label_of(frame, tl.fps.value())});
    if (tty) std::fprintf(stderr, "\rsheet: %zu/%zu frames", tiles.size(), frames.size());
  }
  const std::string title = std::filesystem::path(tl.path).filename().string() + "  " +
                            std::to_string(tl.width) + "x" + std::to_string(tl.height) + ", " +
                            std::to_string(frames.size()) + " of " +
                            std::to_string(tl.frame_count()) + " frames";
  draw::contact_sheet(tiles, o.columns, title).write_png(o.output);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::fprintf(stderr, "%swrote %s: %zu frames (%d to %d) at %dx%d in %.1f s\n", tty ? "\r" : "",
               o.output.c_str(), frames.size(), frames.front(), frames.back(), tl.width, tl.height,
               seconds);
  return 0;
}

}  // namespace

void add_sheet_command(CLI::App& app, int& status) {
  auto o = std::make_shared<SheetOptions>();
  CLI::App* cmd = app.add_subcommand(
      "sheet",
      "a contact sheet: N frames spread over the timeline, small and labelled, in one PNG");
  cmd->add_option("TIMELINE", o->render.timeline_path, "timeline file (TOML)")->required();
  cmd->add_option("-o,--output", o->output, "the sheet, a .png file")->required();
  cmd->add_option("--count", o->count, "frames on the sheet (default 12), spread evenly")
      ->check(CLI::Range(1, 400));
  cmd->add_option("--columns", o->columns, "tiles in a row (default 4)")->check(CLI::Range(1, 64));
  cmd->add_option("--tile-width", o->tile_width,
                  "width of each frame in pixels (default 320; the height keeps the aspect)")
      ->check(CLI::Range(16, 4096));
  cmd->add_option("--frames", o->render.frames,
                  "spread over these frames only, e.g. 0-99 (default: the whole timeline)");
  add_quick_look_options(cmd, o->render);
  cmd->callback([o, &status] { status = run_sheet(*o); });
}

}  // namespace sdfreel
