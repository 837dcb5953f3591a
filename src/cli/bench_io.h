#pragma once
// `sdfreel bench`: time outside the render of one target and backend (bench/io_costs.h).
#include <string>
#include <vector>

#include "bench/io_costs.h"
#include "pipeline/frame_pipeline.h"

namespace sdfreel {

// The bench's default timeline of a scene (its defaults and default camera, 30 fps, 10 s, seed 1;
// the size comes from --resolution) written to `path`, for a command that reads a file. Returns
// `path`.
std::string write_default_timeline(const std::string& scene, const std::string& path);

// Start-up of a still of `timeline_file` (a scene's default timeline is written to `out` when the
// target is a scene name), then each of `frames` rendered with the timeline's own settings and
// written as PNG + EXR into `out`: medians of `repetitions`.
bench::IoRow measure_io_row(const std::string& label, const std::string& timeline_file,
                            FramePipeline& pipe, const std::string& backend,
                            const std::vector<int>& frames, int repetitions,
                            const std::string& out);

// Prints the table and writes out/io.csv.
void report_io_rows(const std::vector<bench::IoRow>& rows, const std::string& out);

}  // namespace sdfreel
