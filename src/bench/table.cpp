#include "bench/table.h"

#include <cmath>
#include <cstdio>

namespace sdfreel::bench {

namespace {

std::string num(const char* f, double v) {
  if (std::isinf(v)) return "inf";
  char b[64];
  std::snprintf(b, sizeof b, f, v);
  return b;
}

}  // namespace

std::string format_table(const std::vector<BenchRow>& rows, bool all) {
  std::string out =
      "| scene | backend | preset | spp | s/frame | PSNR dB | RMSE | p99 abs | hit/miss | "
      "SDF evals/px | front |\n"
      "| --- | --- | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | :---: |\n";
  for (const BenchRow& r : rows) {
    if (!all && !r.named_preset && !r.on_front) continue;
    out += "| " + r.scene + " | " + r.backend + " | " +
           (r.named_preset ? "**" + r.preset + "**" : r.preset) + " | " +
           num("%.3g", r.mean_samples) + " | " + num("%.4f", r.seconds_per_frame) + " | " +
           num("%.2f", r.psnr_db) + " | " + num("%.5f", r.rmse) + " | " +
           num("%.4f", r.p99_abs_error) + " | " + num("%.4f", r.hitmiss_fraction) + " | " +
           num("%.1f", r.sdf_evals_per_pixel) + " | " + (r.on_front ? "yes" : "") + " |\n";
  }
  return out;
}

}  // namespace sdfreel::bench
