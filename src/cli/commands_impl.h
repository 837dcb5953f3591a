#pragma once
// One add_*_command per command file; each sets `status` when its command runs.
#include "cli/render_options.h"
#include "pipeline/errors.h"
#include "pipeline/frame_pipeline.h"

namespace CLI {
class App;
}

namespace sdfreel {

void add_render_command(CLI::App& app, int& status);
void add_still_command(CLI::App& app, int& status);
void add_sheet_command(CLI::App& app, int& status);
void add_verify_command(CLI::App& app, int& status);
void add_encode_command(CLI::App& app, int& status);
void add_scenes_command(CLI::App& app, int& status);
void add_bench_command(CLI::App& app, int& status);
void add_slurm_command(CLI::App& app, int& status);
void add_interlace_command(CLI::App& app, int& status);
void add_devices_command(CLI::App& app, int& status);
void add_generate_command(CLI::App& app, int& status);
void add_check_command(CLI::App& app, int& status);
void add_map_command(CLI::App& app, int& status);

}  // namespace sdfreel
