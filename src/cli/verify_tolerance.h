#pragma once
// `verify --tolerance filament`: frames from another renderer (a GPU, another Mesa) are held to
// the golden PNG frames beside the manifest by Filament's rule (io/display_compare.h) instead of
// by hash. Every selected frame is checked; a diff image is written for each that fails.
#include <string>
#include <vector>

#include "pipeline/frame_pipeline.h"

namespace sdfreel {

// Renders `frames` and compares each with <golden_dir>/frames/NNNNN.png; diff images go to
// out_dir. Prints a line per frame and a summary; returns 0 when every frame passes, else 1.
int verify_within_tolerance(FramePipeline& pipe, const std::vector<int>& frames,
                            const std::string& golden_dir, const std::string& out_dir);

}  // namespace sdfreel
