#include "bench/micro_bench.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdio>
#include <map>
#include <string>

#include "bench/median.h"
#include "bench/micro_check.h"

namespace sdfreel::bench {

namespace {

const char* const RATE_COUNTER = "evals_per_s";

// Where each registered benchmark's median goes.
struct Slot {
  double* rate;
};

// Google Benchmark 1.8 (Debian 13) replaced Run::error_occurred/error_message with
// skipped/skip_message; 1.7 (Debian 12) has only the old pair. The overload that compiles wins.
template <typename R>
auto run_error(const R& r, int) -> decltype(r.skipped, std::string()) {
  return r.skipped ? (r.skip_message.empty() ? "skipped" : r.skip_message) : "";
}
template <typename R>
auto run_error(const R& r, long) -> decltype(r.error_occurred, std::string()) {
  return r.error_occurred ? (r.error_message.empty() ? "error" : r.error_message) : "";
}

// Collects the evaluation rate of every repetition, by registered name, and prints a line per
// repetition to stderr (the machine is shared: a slow outlier is visible, the median drops it).
class RateCollector : public benchmark::BenchmarkReporter {
 public:
  bool ReportContext(const Context&) override { return true; }
  void ReportRuns(const std::vector<Run>& runs) override {
    for (const Run& r : runs) {
      if (r.run_type != Run::RT_Iteration) continue;  // medians are taken here, from every run
      const std::string& name = r.run_name.function_name;
      const std::string error = run_error(r, 0);
      if (!error.empty()) {
        errors_ += name + ": " + error + "\n";
        continue;
      }
      const auto c = r.counters.find(RATE_COUNTER);
      if (c == r.counters.end()) continue;
      rates_[name].push_back(c->second.value);
      std::fprintf(stderr, "bench: micro %-44s %12.4g evals/s\n", name.c_str(), c->second.value);
    }
  }
  const std::map<std::string, std::vector<double>>& rates() const { return rates_; }
  const std::string& errors() const { return errors_; }

 private:
  std::map<std::string, std::vector<double>> rates_;
  std::string errors_;
};

using Evaluate = std::function<void(const float*, const float*, const float*, float*, int)>;

// One timed pass over the points. Out of line and named by path, so that a profiler can count one
// path's instructions alone (scripts/count-flops.sh collects inside evaluate_lanes_pass only).
[[gnu::noinline]] void evaluate_scalar_pass(const Evaluate& fn, const SamplePoints& p, float* d) {
  fn(p.x.data(), p.y.data(), p.z.data(), d, p.size());
}
[[gnu::noinline]] void evaluate_lanes_pass(const Evaluate& fn, const SamplePoints& p, float* d) {
  fn(p.x.data(), p.y.data(), p.z.data(), d, p.size());
}
using Pass = void (*)(const Evaluate&, const SamplePoints&, float*);

void register_one(const std::string& name, Pass pass, const Evaluate& fn,
                  const SamplePoints& points) {
  benchmark::RegisterBenchmark(name.c_str(), [pass, &fn, &points](benchmark::State& state) {
    const int n = points.size();
    std::vector<float> d(n);
    for (auto _ : state) {
      pass(fn, points, d.data());
      benchmark::DoNotOptimize(d.data());
      benchmark::ClobberMemory();
    }
    state.counters[RATE_COUNTER] =
        benchmark::Counter(double(n), benchmark::Counter::kIsIterationInvariantRate);
  });
}

// Google Benchmark reads its settings from flags only: Initialize with a made-up command line.
void initialize_flags(const MicroOptions& o) {
  std::vector<std::string> args = {
      "sdfreel-bench-micro",
      "--benchmark_repetitions=" + std::to_string(o.repetitions),
      "--benchmark_min_time=" + std::to_string(o.min_time),
      "--benchmark_filter=.",
      "--benchmark_enable_random_interleaving=false",
  };
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  int argc = int(args.size());
  benchmark::Initialize(&argc, argv.data());
}

}  // namespace

void check_lanes_match_scalar(const std::vector<MicroTarget>& targets) {
  for (const MicroTarget& t : targets)
    for (const DistanceFunction& fn : t.functions)
      if (const auto m = first_lane_mismatch(fn, t.points))
        throw LaneMismatchError(describe(t.scene, fn.name, *m));
}

std::vector<MicroRow> run_micro_benchmarks(const std::vector<MicroTarget>& targets,
                                           const MicroOptions& options) {
  if (options.repetitions < 1) throw std::invalid_argument("micro: repetitions must be >= 1");
  if (!(options.min_time > 0.0)) throw std::invalid_argument("micro: min time must be > 0");
  check_lanes_match_scalar(targets);

  std::vector<MicroRow> rows;
  for (const MicroTarget& t : targets)
    for (const DistanceFunction& fn : t.functions)
      rows.push_back(MicroRow{t.scene, fn.name, t.points.size(), 0.0, 0.0});
  if (rows.empty()) return rows;

  benchmark::ClearRegisteredBenchmarks();
  for (const MicroTarget& t : targets)
    for (const DistanceFunction& fn : t.functions) {
      const std::string base = t.scene + "/" + fn.name;
      register_one(base + "/scalar", evaluate_scalar_pass, fn.scalar, t.points);
      register_one(base + "/lanes", evaluate_lanes_pass, fn.lanes, t.points);
    }
  initialize_flags(options);
  RateCollector collector;
  benchmark::RunSpecifiedBenchmarks(&collector);
  benchmark::ClearRegisteredBenchmarks();
  if (!collector.errors().empty())
    throw std::runtime_error("micro-benchmark failed:\n" + collector.errors());

  for (MicroRow& r : rows) {
    const std::string base = r.scene + "/" + r.function;
    const auto s = collector.rates().find(base + "/scalar");
    const auto l = collector.rates().find(base + "/lanes");
    if (s != collector.rates().end()) r.scalar_evals_per_s = median_of(s->second);
    if (l != collector.rates().end()) r.lanes_evals_per_s = median_of(l->second);
  }
  return rows;
}

}  // namespace sdfreel::bench
