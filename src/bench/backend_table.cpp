#include "bench/backend_table.h"

#include <cstdio>

namespace sdfreel::bench {

namespace {

const BenchRow* find_row(const std::vector<BenchRow>& rows, const std::string& scene,
                         const std::string& backend, const std::string& preset) {
  for (const BenchRow& r : rows)
    if (r.scene == scene && r.backend == backend && r.preset == preset) return &r;
  return nullptr;
}

}  // namespace

std::vector<BackendComparison> compare_backends(const std::vector<BenchRow>& rows) {
  std::vector<BackendComparison> out;
  for (const BenchRow& cpu : rows) {
    if (cpu.backend != "cpu" || !cpu.named_preset) continue;
    const BenchRow* gl = find_row(rows, cpu.scene, "osmesa", cpu.preset);
    if (!gl) continue;
    out.push_back({cpu.scene, cpu.preset, cpu.seconds_per_frame, gl->seconds_per_frame, cpu.psnr_db,
                   gl->psnr_db});
  }
  return out;
}

std::string format_backend_table(const std::vector<BackendComparison>& cmp) {
  std::string out =
      "| scene | preset | CPU s/frame | OSMesa s/frame | OSMesa / CPU | CPU PSNR dB | OSMesa PSNR "
      "dB | CPU >= 2x, error <= |\n"
      "| --- | --- | ---: | ---: | ---: | ---: | ---: | :---: |\n";
  for (const BackendComparison& c : cmp) {
    char line[512];
    std::snprintf(line, sizeof line, "| %s | %s | %.4f | %.4f | %.2fx | %.2f | %.2f | %s |\n",
                  c.scene.c_str(), c.preset.c_str(), c.cpu_seconds, c.osmesa_seconds, c.speedup(),
                  c.cpu_psnr_db, c.osmesa_psnr_db, c.meets_target() ? "yes" : "**no**");
    out += line;
  }
  return out;
}

}  // namespace sdfreel::bench
