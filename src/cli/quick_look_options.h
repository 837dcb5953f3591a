#pragma once
// The options of the commands that make a quick picture of a timeline (sheet, map): render's
// backend and thread options, and --samples and --quality defaulting to a preview's look (one
// sample, draft) instead of the timeline's.
#include "cli/render_options.h"

namespace sdfreel {

void add_quick_look_options(CLI::App* cmd, RenderOptions& o);
// One sample and draft quality where --samples and --quality did not say otherwise.
void apply_quick_look(const RenderOptions& o, Timeline& tl);

}  // namespace sdfreel
