#include "bench/csv.h"

#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>

#include "io/atomic_file.h"

namespace sdfreel::bench {

namespace {

std::string num(double v) {
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  char b[64];
  std::snprintf(b, sizeof b, "%.6g", v);
  return b;
}

}  // namespace

std::vector<std::string> csv_columns() {
  return {"scene",
          "backend",
          "preset",
          "seconds_per_frame",
          "psnr_db",
          "rmse",
          "mean_abs_error",
          "p99_abs_error",
          "hitmiss_fraction",
          "sdf_evals_per_pixel",
          "capped_per_pixel",
          "on_front",
          "samples",
          "mean_samples",
          "max_steps",
          "hit_eps",
          "step_factor",
          "normal_eps",
          "naive"};
}

void write_csv(std::ostream& out, const std::vector<BenchRow>& rows) {
  const std::vector<std::string> cols = csv_columns();
  for (size_t i = 0; i < cols.size(); ++i) out << (i ? "," : "") << cols[i];
  out << "\n";
  for (const BenchRow& r : rows) {
    const std::vector<std::string> cells = {r.scene,
                                            r.backend,
                                            r.preset,
                                            num(r.seconds_per_frame),
                                            num(r.psnr_db),
                                            num(r.rmse),
                                            num(r.mean_abs_error),
                                            num(r.p99_abs_error),
                                            num(r.hitmiss_fraction),
                                            num(r.sdf_evals_per_pixel),
                                            num(r.capped_per_pixel),
                                            r.on_front ? "1" : "0",
                                            std::to_string(r.samples),
                                            num(r.mean_samples),
                                            std::to_string(r.march.max_steps),
                                            num(r.march.hit_eps),
                                            num(r.march.step_factor),
                                            num(r.march.normal_eps),
                                            r.march.naive ? "1" : "0"};
    for (size_t i = 0; i < cells.size(); ++i) out << (i ? "," : "") << cells[i];
    out << "\n";
  }
}

void write_file_via_temp(const std::string& path, const std::function<void(std::ostream&)>& write) {
  std::ostringstream text;
  write(text);
  write_file_atomic(path, text.str());
}

void write_csv_file(const std::string& path, const std::vector<BenchRow>& rows) {
  write_file_via_temp(path, [&rows](std::ostream& out) { write_csv(out, rows); });
}

std::vector<std::string> split_csv_line(const std::string& line) {
  std::vector<std::string> out;
  size_t start = 0;
  while (true) {
    const size_t comma = line.find(',', start);
    out.push_back(
        line.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return out;
}

}  // namespace sdfreel::bench
