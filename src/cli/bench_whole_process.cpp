#include "cli/bench_whole_process.h"

#include <cstdio>
#include <filesystem>
#include <map>
#include <stdexcept>

#include "bench/median.h"
#include "bench/whole_process.h"
#include "io/atomic_file.h"

namespace sdfreel {

int run_whole_process(const std::vector<WholeProcessTarget>& targets,
                      const WholeProcessOptions& o) {
  const std::string exe = std::filesystem::read_symlink("/proc/self/exe").string();
  const std::string work = o.out + "/whole";
  std::filesystem::create_directories(work);
  // Times per (target, backend); a backend that fails once is dropped for that target.
  std::map<std::pair<size_t, std::string>, std::vector<bench::ProcessTime>> times;
  std::map<std::pair<size_t, std::string>, bool> failed;
  // One untimed run each first (generated textures, caches), then the repetitions, the backends
  // alternating within each.
  for (int rep = 0; rep <= o.repetitions; ++rep)
    for (size_t i = 0; i < targets.size(); ++i)
      for (const std::string& backend : o.backends) {
        const auto key = std::make_pair(i, backend);
        if (failed[key]) continue;
        const WholeProcessTarget& t = targets[i];
        const std::string dir = work + "/" + t.label + "-" + backend;
        std::filesystem::remove_all(dir);  // every frame rendered again, none kept
        std::vector<std::string> argv = {exe};
        for (const std::string& a :
             bench::whole_process_args(t.timeline_file, o.frames, t.resolution, backend, dir))
          argv.push_back(a);
        std::fprintf(stderr, "bench: %s %s whole process, %s\n", t.label.c_str(), backend.c_str(),
                     rep == 0 ? "untimed first run"
                              : ("repetition " + std::to_string(rep) + " of " +
                                 std::to_string(o.repetitions))
                                    .c_str());
        try {
          const bench::ProcessTime pt = bench::run_timed(argv, "the render");
          if (rep > 0) times[key].push_back(pt);
        } catch (const std::exception& e) {
          std::fprintf(stderr, "bench: skipping %s on %s: %s\n", t.label.c_str(), backend.c_str(),
                       e.what());
          failed[key] = true;
        }
      }
  std::vector<bench::WholeProcessRow> rows;
  for (size_t i = 0; i < targets.size(); ++i)
    for (const std::string& backend : o.backends) {
      const auto it = times.find({i, backend});
      if (it == times.end() || it->second.empty()) continue;
      std::vector<double> wall, cpu;
      for (const bench::ProcessTime& pt : it->second)
        wall.push_back(pt.wall_seconds), cpu.push_back(pt.cpu_seconds);
      const WholeProcessTarget& t = targets[i];
      rows.push_back({t.label,
                      backend,
                      t.frames,
                      t.width,
                      t.height,
                      t.samples,
                      {bench::median_of(wall), bench::median_of(cpu)}});
    }
  if (rows.empty()) return 1;
  std::printf(
      "whole process (`sdfreel render --frames %s --no-video`, a fresh process each, "
      "medians of %d):\n%s",
      o.frames.c_str(), o.repetitions, bench::format_whole_process_table(rows).c_str());
  write_file_atomic(o.out + "/whole_process.csv", bench::whole_process_csv(rows));
  std::printf("csv: %s/whole_process.csv\n", o.out.c_str());
  return 0;
}

}  // namespace sdfreel
