#include "bench/whole_process.h"

#include <cstdio>

namespace sdfreel::bench {

namespace {

// The CPU's row for the same scene, or null.
const WholeProcessRow* cpu_row(const std::vector<WholeProcessRow>& rows, const std::string& scene) {
  for (const WholeProcessRow& r : rows)
    if (r.scene == scene && r.backend == "cpu") return &r;
  return nullptr;
}

}  // namespace

std::vector<std::string> whole_process_args(const std::string& timeline, const std::string& frames,
                                            const std::string& resolution,
                                            const std::string& backend, const std::string& out) {
  std::vector<std::string> a = {"render",    timeline, "--frames", frames, "--no-video",
                                "--backend", backend,  "--out",    out};
  if (!resolution.empty()) a.insert(a.end(), {"--resolution", resolution});
  return a;
}

std::string format_whole_process_table(const std::vector<WholeProcessRow>& rows) {
  std::string out =
      "| scene | size | samples | frames | backend | wall s | s/frame | CPU s | time / cpu's |\n"
      "| --- | --- | --- | ---: | --- | ---: | ---: | ---: | ---: |\n";
  for (const WholeProcessRow& r : rows) {
    const WholeProcessRow* cpu = cpu_row(rows, r.scene);
    char ratio[32] = "";
    if (cpu && r.backend != "cpu" && cpu->time.wall_seconds > 0.0)
      std::snprintf(ratio, sizeof ratio, "%.2fx", r.time.wall_seconds / cpu->time.wall_seconds);
    char line[512];
    std::snprintf(line, sizeof line, "| %s | %dx%d | %s | %d | %s | %.2f | %.3f | %.2f | %s |\n",
                  r.scene.c_str(), r.width, r.height, r.samples.c_str(), r.frames,
                  r.backend.c_str(), r.time.wall_seconds,
                  r.frames > 0 ? r.time.wall_seconds / r.frames : 0.0, r.time.cpu_seconds, ratio);
    out += line;
  }
  return out;
}

std::string whole_process_csv(const std::vector<WholeProcessRow>& rows) {
  std::string csv = "scene,backend,width,height,samples,frames,wall_seconds,cpu_seconds\n";
  for (const WholeProcessRow& r : rows) {
    char line[512];
    std::snprintf(line, sizeof line, "%s,%s,%d,%d,%s,%d,%.6f,%.6f\n", r.scene.c_str(),
                  r.backend.c_str(), r.width, r.height, r.samples.c_str(), r.frames,
                  r.time.wall_seconds, r.time.cpu_seconds);
    csv += line;
  }
  return csv;
}

}  // namespace sdfreel::bench
