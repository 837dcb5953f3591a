#include <CLI/CLI.hpp>
#include <cstdio>

#include "cli/commands.h"
#include "cli/commands_impl.h"
#include "timeline/timeline.h"

namespace sdfreel {

int run_cli(int argc, char** argv) {
  CLI::App app{"sdfreel: deterministic renders of procedural shader scenes to frames and video"};
  app.set_version_flag("--version", std::string("sdfreel ") + SDFREEL_VERSION);
  app.require_subcommand(1);
  int status = 0;
  add_render_command(app, status);
  add_still_command(app, status);
  add_sheet_command(app, status);
  add_check_command(app, status);
  add_map_command(app, status);
  add_verify_command(app, status);
  add_encode_command(app, status);
  add_scenes_command(app, status);
  add_bench_command(app, status);
  add_slurm_command(app, status);
  add_interlace_command(app, status);
  add_devices_command(app, status);
  add_generate_command(app, status);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);  // prints help or the usage error
    return code == 0 ? 0 : 2;
  } catch (const InputError& e) {
    std::fprintf(stderr, "%s\n", e.formatted().c_str());
    return 2;
  } catch (const UsageError& e) {
    std::fprintf(stderr, "sdfreel: error: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "sdfreel: error: %s\n", e.what());
    return 1;
  }
  return status;
}

}  // namespace sdfreel
