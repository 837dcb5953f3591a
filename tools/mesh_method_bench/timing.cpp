#include "timing.h"

#include <algorithm>
#include <chrono>
#include <ctime>

namespace sdfreel::mesh_bench {
namespace {

double cpu_ms_now() {
  timespec t;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) * 1e3 + double(t.tv_nsec) * 1e-6;
}

}  // namespace

Elapsed time_call(const std::function<void()>& fn) {
  const double c0 = cpu_ms_now();
  const auto w0 = std::chrono::steady_clock::now();
  fn();
  const double wall =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - w0).count();
  return {cpu_ms_now() - c0, wall};
}

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

}  // namespace sdfreel::mesh_bench
