#pragma once
// Time outside the render, measured by `sdfreel bench` next to the render time: the start-up of a
// `sdfreel still` of a small frame (a fresh process: libraries, colour set-up, backend set-up,
// generated textures), and writing one frame's files (PNG + EXR, encoded and published as
// `render` does).
#include <string>
#include <vector>

#include "bench/process_time.h"
#include "render/image.h"

namespace sdfreel::bench {

// The still that measures start-up: 64x36, one frame, so that rendering is a few milliseconds.
constexpr const char* STARTUP_RESOLUTION = "64x36";

using StartupTime = ProcessTime;  // medians of the timed runs

// Runs `exe still TIMELINE --time 0 --resolution 64x36 --backend BACKEND -o FOLDER/startup.png`
// once to fill the cache folder, then `repetitions` times timed. Throws std::runtime_error if a
// run fails.
StartupTime measure_startup(const std::string& exe, const std::string& timeline,
                            const std::string& backend, int repetitions, const std::string& folder);

// Seconds to write `linear` as EXR and `display` as PNG into `folder` (frame_files.h).
double time_frame_write(const ImageRGBA& linear, const ImageRGB16& display,
                        const std::string& folder);

struct IoRow {
  std::string scene, backend;
  StartupTime startup;
  double render_seconds = 0.0;  // per frame, the timeline's own settings, median
  double write_seconds = 0.0;   // per frame, PNG + EXR, median
};

// Markdown table of the rows.
std::string format_io_table(const std::vector<IoRow>& rows);

}  // namespace sdfreel::bench
