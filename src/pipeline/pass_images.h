#pragma once
// The compositing passes of a rendered frame (render/compositing_passes.h), gathered from what
// the backend kept of it.
#include <string>
#include <vector>

#include "render/backend.h"
#include "render/compositing_passes.h"

namespace sdfreel {

// Tells the backend which of them need it to record more than it does by default (before begin).
void record_passes(const std::vector<std::string>& names, Backend& backend);
// The passes `names` of the frame `backend` rendered last, at its size. Throws std::logic_error
// for a pass the backend did not record.
std::vector<PassImage> pass_images(const std::vector<std::string>& names, const Backend& backend,
                                   int width, int height);

}  // namespace sdfreel
