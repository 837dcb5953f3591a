#pragma once
// The compositing passes of a rendered frame (render/compositing_passes.h): what the backend kept
// of the frame (samples, sdf_evals), and what it renders again in another mode (id, depth,
// normal).
#include <string>
#include <vector>

#include "render/backend.h"
#include "render/compositing_passes.h"

namespace sdfreel {

// Tells the backend which of them need it to record more than it does by default (before begin).
void record_passes(const std::vector<std::string>& names, Backend& backend);
// The passes `names` of frame `ctx`, which `backend` rendered last, in that order. "id", "depth"
// and "normal" each render the frame once more, one ray through each pixel's centre, in a mode
// that draws the surface's id, distance or normal (MarchSettings::hit_mask, ::surface), so they
// come after what was kept of the frame itself. Throws
// std::logic_error for a pass the backend did not record.
std::vector<PassImage> pass_images(const std::vector<std::string>& names, Backend& backend,
                                   const FrameContext& ctx);

}  // namespace sdfreel
