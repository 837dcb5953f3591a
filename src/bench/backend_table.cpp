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

std::vector<BackendComparison> compare_backends(const std::vector<BenchRow>& rows,
                                                const std::string& base, const std::string& other) {
  std::vector<BackendComparison> out;
  for (const BenchRow& a : rows) {
    if (a.backend != base || !a.named_preset) continue;
    const BenchRow* b = find_row(rows, a.scene, other, a.preset);
    if (!b) continue;
    out.push_back({a.scene, a.preset, base, other, a.seconds_per_frame, b->seconds_per_frame,
                   a.psnr_db, b->psnr_db});
  }
  return out;
}

std::string format_backend_table(const std::vector<BackendComparison>& cmp, bool with_target) {
  if (cmp.empty()) return "";
  const char* a = cmp[0].base.c_str();
  const char* b = cmp[0].other.c_str();
  char head[512];
  std::snprintf(
      head, sizeof head,
      "| scene | preset | %s s/frame | %s s/frame | %s / %s | %s PSNR dB | %s PSNR dB |%s\n"
      "| --- | --- | ---: | ---: | ---: | ---: | ---: |%s\n",
      a, b, b, a, a, b, with_target ? " CPU >= 2x, error <= |" : "", with_target ? " :---: |" : "");
  std::string out = head;
  for (const BackendComparison& c : cmp) {
    char line[512];
    std::snprintf(line, sizeof line, "| %s | %s | %.4f | %.4f | %.2fx | %.2f | %.2f |%s\n",
                  c.scene.c_str(), c.preset.c_str(), c.base_seconds, c.other_seconds, c.speedup(),
                  c.base_psnr_db, c.other_psnr_db,
                  !with_target       ? ""
                  : c.meets_target() ? " yes |"
                                     : " **no** |");
    out += line;
  }
  return out;
}

}  // namespace sdfreel::bench
