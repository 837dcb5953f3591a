#include "cli/quick_look_options.h"

#include <CLI/CLI.hpp>

namespace sdfreel {

void add_quick_look_options(CLI::App* cmd, RenderOptions& o) {
  add_backend_options(cmd, o);
  cmd->add_option("--threads", o.threads, "worker threads (default: all cores)")
      ->check(CLI::Range(1, 1024));
  cmd->add_option("--samples", o.samples, "samples per pixel (default 1)")
      ->check(CLI::Range(1, 1024));
  cmd->add_option("--quality", o.quality, "draft (default) | final | reference")
      ->check(CLI::IsMember({"draft", "final", "reference"}));
}

void apply_quick_look(const RenderOptions& o, Timeline& tl) {
  if (!o.samples) {
    tl.samples = 1;
    tl.adaptive.enabled = false;
  }
  if (o.quality.empty()) tl.quality = Quality::Draft;
}

}  // namespace sdfreel
