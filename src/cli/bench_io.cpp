#include "cli/bench_io.h"

#include <cstdio>
#include <filesystem>

#include "bench/median.h"
#include "io/atomic_file.h"

namespace sdfreel {

std::string write_default_timeline(const std::string& scene, const std::string& path) {
  write_file_atomic(path,
                    "[video]\nscene = \"" + scene + "\"\nfps = 30\nduration = 10.0\nseed = 1\n");
  return path;
}

bench::IoRow measure_io_row(const std::string& label, const std::string& timeline_file,
                            FramePipeline& pipe, const std::string& backend,
                            const std::vector<int>& frames, int repetitions,
                            const std::string& out) {
  const std::string folder = out + "/io";
  std::filesystem::create_directories(folder);
  const std::string timeline =
      std::filesystem::is_regular_file(timeline_file)
          ? timeline_file
          : write_default_timeline(pipe.timeline().scene,
                                   folder + "/startup-" + pipe.timeline().scene + ".toml");
  bench::IoRow row;
  row.scene = label;
  row.backend = backend;
  row.startup = bench::measure_startup(std::filesystem::read_symlink("/proc/self/exe").string(),
                                       timeline, backend, repetitions, folder);
  std::vector<double> render, write;
  for (int rep = 0; rep < repetitions; ++rep)
    for (int frame : frames) {
      const RenderedFrame f = pipe.render(frame);
      render.push_back(f.seconds);
      write.push_back(bench::time_frame_write(f.linear, f.display, folder));
    }
  row.render_seconds = bench::median_of(render);
  row.write_seconds = bench::median_of(write);
  return row;
}

void report_io_rows(const std::vector<bench::IoRow>& rows, const std::string& out) {
  if (rows.empty()) return;
  std::printf(
      "\ntime outside the render (start-up: a fresh `sdfreel still` at %s, cache folder warm; "
      "render and write: the timeline's own settings at the bench size; medians):\n%s",
      bench::STARTUP_RESOLUTION, bench::format_io_table(rows).c_str());
  std::string csv =
      "scene,backend,startup_wall_seconds,startup_cpu_seconds,render_seconds_per_frame,"
      "write_seconds_per_frame\n";
  for (const bench::IoRow& r : rows) {
    char line[512];
    std::snprintf(line, sizeof line, "%s,%s,%.6f,%.6f,%.6f,%.6f\n", r.scene.c_str(),
                  r.backend.c_str(), r.startup.wall_seconds, r.startup.cpu_seconds,
                  r.render_seconds, r.write_seconds);
    csv += line;
  }
  write_file_atomic(out + "/io.csv", csv);
  std::printf("csv: %s/io.csv\n", out.c_str());
}

}  // namespace sdfreel
