// `sdfreel interlace VIEW... -o PRINT --lpi L --dpi D`: the interlaced image of N views for a
// real lenticular card (src/scenes/lenticular_card/interlace.h). Views come as files in order or
// as a printf pattern with --views N. Bad input exits 2 before anything is written.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "cli/commands_impl.h"
#include "io/atomic_file.h"
#include "io/png_file.h"
#include "scenes/lenticular_card/interlace.h"
#include "scenes/lenticular_card/ppm.h"

namespace sdfreel {
namespace {

using lenticular_card::Rgb8Image;

struct InterlaceOptions {
  std::vector<std::string> files;
  std::string pattern, output;
  int views = 0;
  double lpi = 0.0, dpi = 0.0;
};

bool has_suffix(const std::string& name, const std::string& suffix) {
  return name.size() >= suffix.size() &&
         name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// Views and prints are 8-bit RGB: PNG (what sdfreel writes) or binary PPM.
bool known_format(const std::string& path) {
  return has_suffix(path, ".png") || has_suffix(path, ".ppm");
}

Rgb8Image read_view(const std::string& path) {
  if (!known_format(path)) throw UsageError(path + ": views are .png or .ppm files");
  Rgb8Image img;
  if (has_suffix(path, ".ppm")) {
    if (!lenticular_card::read_ppm(path, img))
      throw UsageError(path + ": cannot read the view (expected a binary P6 PPM, maxval 255)");
    return img;
  }
  PngPixels png;
  try {
    png = read_png(path, 3);
  } catch (const std::exception& e) {
    throw UsageError(std::string("cannot read the view: ") + e.what());
  }
  img = Rgb8Image(png.width, png.height);
  for (size_t i = 0; i < img.rgb.size(); ++i) img.rgb[i] = uint8_t(png.samples[i] / 257);
  return img;
}

std::vector<std::string> view_paths(const InterlaceOptions& o) {
  if (!o.pattern.empty() && !o.files.empty())
    throw UsageError("interlace: give the views as files or as --pattern, not both");
  if (o.pattern.empty()) {
    if (o.views != 0 && o.views != int(o.files.size()))
      throw UsageError("interlace: --views " + std::to_string(o.views) + " but " +
                       std::to_string(o.files.size()) + " view files");
    return o.files;
  }
  if (o.views < 2) throw UsageError("interlace: --pattern needs --views N (N >= 2)");
  if (o.pattern.find('%') == std::string::npos)
    throw UsageError("interlace: --pattern '" + o.pattern + "' has no %d for the view number");
  std::vector<std::string> out;
  for (int i = 0; i < o.views; ++i) {
    char name[4096];
    std::snprintf(name, sizeof name, o.pattern.c_str(), i);
    out.push_back(name);
  }
  return out;
}

void write_print(const std::string& path, const Rgb8Image& print) {
  if (has_suffix(path, ".ppm")) {
    const std::string bytes = lenticular_card::encode_ppm(print);
    write_file_atomic(path, bytes.data(), bytes.size());
    return;
  }
  const std::vector<unsigned char> bytes =
      encode_png(print.width, print.height, 3, 8, print.rgb.data(), PngCompression{9, -1, 0});
  write_file_atomic(path, bytes.data(), bytes.size());
}

int run_interlace(const InterlaceOptions& o) {
  const std::vector<std::string> paths = view_paths(o);
  if (paths.size() < 2) throw UsageError("interlace: needs at least 2 views");
  // Check the output's format before reading anything big: a bad name writes nothing.
  if (!known_format(o.output))
    throw UsageError(o.output + ": no image format for this file name (.png or .ppm)");
  std::vector<Rgb8Image> views;
  for (const std::string& p : paths) {
    views.push_back(read_view(p));
    if (views.back().width != views[0].width || views.back().height != views[0].height)
      throw UsageError(p + ": " + std::to_string(views.back().width) + "x" +
                       std::to_string(views.back().height) + ", but " + paths[0] + " is " +
                       std::to_string(views[0].width) + "x" + std::to_string(views[0].height));
  }
  const auto layout = lenticular_card::print_layout(int(views.size()), o.lpi, o.dpi);
  const std::string problem =
      lenticular_card::layout_problem(layout, views[0].width, views[0].height);
  if (!problem.empty()) throw UsageError("interlace: " + problem);
  const Rgb8Image print = lenticular_card::interlace(views, layout);
  write_print(o.output, print);
  std::printf("%s: %dx%d pixels, %zu views, %g lenses per inch at %g dpi: %.3f x %.3f inches\n",
              o.output.c_str(), print.width, print.height, views.size(), o.lpi, o.dpi,
              print.width / o.dpi, print.height / o.dpi);
  return 0;
}

}  // namespace

void add_interlace_command(CLI::App& app, int& status) {
  auto o = std::make_shared<InterlaceOptions>();
  CLI::App* cmd = app.add_subcommand(
      "interlace", "interlace N views into the print of a lenticular card (one lens a column)");
  cmd->add_option("VIEWS", o->files, "view images in order (all the same size)");
  cmd->add_option("--pattern", o->pattern, "printf pattern of the view files, e.g. v%02d.png");
  cmd->add_option("--views", o->views, "number of views (with --pattern)")
      ->check(CLI::Range(2, 1024));
  cmd->add_option("--lpi", o->lpi, "lenses per inch of the sheet")
      ->required()
      ->check(CLI::Range(1e-3, 1e4));
  cmd->add_option("--dpi", o->dpi, "print resolution, dots per inch")
      ->required()
      ->check(CLI::Range(1e-3, 1e6));
  cmd->add_option("-o,--output", o->output, "the interlaced image (.png or .ppm)")->required();
  cmd->callback([o, &status] { status = run_interlace(*o); });
}

}  // namespace sdfreel
