#pragma once
// Source views (seed 004, exhibit 2, step 1): N pictures of one of our scenes from slightly
// different angles, rendered by sdfreel itself and kept on disk by content key, so they are made
// once and every backend reads the same bytes.
//
// View i looks at the scene's default camera target from its default camera rotated about the
// vertical through the target by (i / (N - 1) - 0.5) * orbit_deg: view N - 1 from the right, as
// the card shows it to a viewer on the right. The scene's own ray passes render it (the CPU path,
// Scene::frame_plan's scalar functions), then exposure 1 - exp(-x) and the sRGB curve make the
// 8-bit picture a print would carry.
#include <string>
#include <vector>

#include "render/camera.h"
#include "scenes/lenticular_card/interlace.h"

namespace sdfreel::lenticular_card {

struct ViewSet {
  std::string scene;  // a registered scene made of ray passes only
  int views = 16;     // N
  int width = 64, height = 48;
  int samples = 2;          // sub-pixel samples of each view
  double time = 0.0;        // the scene's TIME, seconds
  double orbit_deg = 24.0;  // the angle between the first and the last view
  double zoom = 1.0;        // the default camera's field of view divided by this
};

// The camera of view i.
CameraPose view_pose(const ViewSet& set, int i);

// The cache key of view i: scene, camera, size, samples and time (io/cache_file.h adds the
// build).
std::string view_key(const ViewSet& set, int i);

// View i rendered now (no cache).
Rgb8Image render_view(const ViewSet& set, int i);

// All views: each read from the cache (io/cache_file.h, kind "lenticular": checked on read, so a
// damaged file is rendered again) when there, else rendered and stored (best effort).
std::vector<Rgb8Image> source_views(const ViewSet& set);

}  // namespace sdfreel::lenticular_card
