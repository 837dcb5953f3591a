#include "bench/io_costs.h"

#include <chrono>

#include "bench/median.h"
#include "bench/process_time.h"
#include "io/frame_files.h"

namespace sdfreel::bench {

StartupTime measure_startup(const std::string& exe, const std::string& timeline,
                            const std::string& backend, int repetitions,
                            const std::string& folder) {
  const std::vector<std::string> argv = {exe,
                                         "still",
                                         timeline,
                                         "--time",
                                         "0",
                                         "--resolution",
                                         STARTUP_RESOLUTION,
                                         "--backend",
                                         backend,
                                         "-o",
                                         folder + "/startup.png"};
  run_timed(argv, "the start-up still");  // fills the cache folder (generated textures)
  std::vector<double> wall, cpu;
  for (int i = 0; i < repetitions; ++i) {
    const ProcessTime t = run_timed(argv, "the start-up still");
    wall.push_back(t.wall_seconds);
    cpu.push_back(t.cpu_seconds);
  }
  return {median_of(wall), median_of(cpu)};
}

double time_frame_write(const ImageRGBA& linear, const ImageRGB16& display,
                        const std::string& folder) {
  const auto start = std::chrono::steady_clock::now();
  write_exr_atomic(folder + "/write-test.exr", linear, {{"bench", "write time"}});
  write_png16_atomic(folder + "/write-test.png", display);
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::string format_io_table(const std::vector<IoRow>& rows) {
  std::string out =
      "| scene | backend | start-up s (wall) | start-up CPU s | render s/frame | write s/frame "
      "(PNG + EXR) |\n| --- | --- | ---: | ---: | ---: | ---: |\n";
  for (const IoRow& r : rows) {
    char line[512];
    std::snprintf(line, sizeof line, "| %s | %s | %.3f | %.3f | %.4f | %.4f |\n", r.scene.c_str(),
                  r.backend.c_str(), r.startup.wall_seconds, r.startup.cpu_seconds,
                  r.render_seconds, r.write_seconds);
    out += line;
  }
  return out;
}

}  // namespace sdfreel::bench
