#pragma once
// Pictures of what the methods found, to look at: each triangle id in a colour of its own (first
// sample), and where the methods differ in any sample: red for different triangles, yellow for
// depth ties, green where one drew and the other did not, over the rasteriser's ids dimmed.
#include <string>

#include "render/camera_model.h"
#include "sample_hits.h"

namespace sdfreel::mesh_bench {

// Writes <dir>/<name>_raster.png, <name>_embree.png and <name>_diff.png.
void write_id_images(const std::string& dir, const std::string& name, const SampleHits& raster,
                     const SampleHits& embree, const CameraModel& camera);

}  // namespace sdfreel::mesh_bench
