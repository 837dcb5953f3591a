#include "bench/micro_report.h"

#include <cstdio>

#include "bench/csv.h"

namespace sdfreel::bench {

namespace {

std::string num(const char* format, double v) {
  char b[64];
  std::snprintf(b, sizeof b, format, v);
  return b;
}

}  // namespace

std::string format_micro_table(const std::vector<MicroRow>& rows) {
  std::string out =
      "| scene | function | scalar evals/s | lanes evals/s | lanes/scalar |\n"
      "| --- | --- | ---: | ---: | ---: |\n";
  for (const MicroRow& r : rows)
    out += "| " + r.scene + " | " + r.function + " | " + num("%.4g", r.scalar_evals_per_s) + " | " +
           num("%.4g", r.lanes_evals_per_s) + " | " + num("%.2fx", r.lanes_over_scalar()) + " |\n";
  return out;
}

void write_micro_csv(std::ostream& out, const std::vector<MicroRow>& rows) {
  out << "scene,function,points,scalar_evals_per_s,lanes_evals_per_s,lanes_over_scalar\n";
  for (const MicroRow& r : rows)
    out << r.scene << ',' << r.function << ',' << r.points << ','
        << num("%.6g", r.scalar_evals_per_s) << ',' << num("%.6g", r.lanes_evals_per_s) << ','
        << num("%.4f", r.lanes_over_scalar()) << '\n';
}

void write_micro_csv_file(const std::string& path, const std::vector<MicroRow>& rows) {
  write_file_via_temp(path, [&rows](std::ostream& out) { write_micro_csv(out, rows); });
}

}  // namespace sdfreel::bench
