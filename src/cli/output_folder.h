#pragma once
// Layout of a render's output folder (docs/cli.md) and the manifest header of a render.
#include <string>

#include "io/manifest.h"
#include "pipeline/frame_pipeline.h"

namespace sdfreel {

std::string frame_path(const std::string& dir, int index, const std::string& ext);
// Throws UsageError when `dir` cannot be a folder because it, or a folder above it, is a file:
// found before anything is written.
void check_output_folder(const std::string& dir);
ManifestHeader manifest_header(const Timeline& tl, Backend& backend);

// Reads frame `index` back from `dir` and checks it against the manifest entry: PNG against the
// display hash, EXR against the linear hash. Returns the display pixels (from the PNG, or from the
// EXR through `display`), or nothing when a file is missing or differs.
std::optional<ImageRGB16> load_checked_frame(const std::string& dir, const ManifestHeader& header,
                                             const ManifestFrame& entry,
                                             const DisplayTransform& display,
                                             std::string* why = nullptr);

}  // namespace sdfreel
