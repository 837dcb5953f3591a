// `sdfreel bench [SCENE...]`: seconds per frame of each scene, backend and quality preset, timed
// by Google Benchmark (median of repetitions) on the same frames in one run.
#include <benchmark/benchmark.h>

#include <CLI/CLI.hpp>
#include <cstdio>

#include "cli/commands_impl.h"
#include "cli/frame_range.h"
#include "scenes/registry.h"

namespace sdfreel {

namespace {

struct BenchOptions {
  std::vector<std::string> scenes;
  std::string resolution = "320x180";
  std::string frames = "0-2";
  std::string backends = "cpu";
  std::string qualities = "draft,final";
  int samples = 1;
  int repetitions = 3;
  int threads = 0;
};

std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> out;
  size_t start = 0;
  while (start <= s.size()) {
    const size_t comma = s.find(',', start);
    const std::string part = s.substr(start, comma == std::string::npos ? comma : comma - start);
    if (!part.empty()) out.push_back(part);
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return out;
}

// A timeline for the bench: the scene's defaults, its default camera, 30 fps.
Timeline bench_timeline(const std::string& scene, int w, int h, int samples, Quality q) {
  Timeline tl;
  tl.path = "(bench)";
  tl.scene = scene;
  tl.width = w;
  tl.height = h;
  tl.samples = samples;
  tl.quality = q;
  tl.duration = 10.0;
  return tl;
}

int run_bench(const BenchOptions& o) {
  int w = 0, h = 0;
  if (std::sscanf(o.resolution.c_str(), "%dx%d", &w, &h) != 2 || w < 1 || h < 1)
    throw UsageError("--resolution '" + o.resolution + "': expected WxH");
  std::vector<std::string> scenes = o.scenes;
  if (scenes.empty())
    for (const SceneInfo& s : all_scenes()) scenes.push_back(s.name);
  for (const std::string& s : scenes)
    if (!find_scene(s)) throw UsageError("unknown scene '" + s + "'");
  std::vector<Quality> qualities;
  for (const std::string& q : split(o.qualities)) {
    auto parsed = parse_quality(q);
    if (!parsed) throw UsageError("unknown quality '" + q + "'");
    qualities.push_back(*parsed);
  }
  // Timelines and pipelines live until RunSpecifiedBenchmarks returns.
  std::vector<std::unique_ptr<Timeline>> timelines;
  std::vector<std::unique_ptr<FramePipeline>> pipelines;
  for (const std::string& scene : scenes)
    for (const std::string& backend : split(o.backends))
      for (Quality q : qualities) {
        timelines.push_back(std::make_unique<Timeline>(bench_timeline(scene, w, h, o.samples, q)));
        const std::vector<int> frames = parse_frame_list(o.frames, timelines.back()->frame_count());
        pipelines.push_back(
            std::make_unique<FramePipeline>(*timelines.back(), make_backend(backend, o.threads)));
        FramePipeline* pipe = pipelines.back().get();
        const std::string name = scene + "/" + backend + "/" + quality_name(q);
        benchmark::RegisterBenchmark(
            name.c_str(),
            [pipe, frames](benchmark::State& state) {
              size_t k = 0;
              double evals = 0.0;
              for (auto _ : state) {
                RenderedFrame f = pipe->render(frames[k++ % frames.size()]);
                evals += double(f.stats.sdf_evals);
                benchmark::DoNotOptimize(f.display.pixels.data());
              }
              const double pixels = double(pipe->timeline().width) * pipe->timeline().height;
              state.counters["sdf_evals_per_pixel"] = evals / (pixels * double(state.iterations()));
            })
            ->Unit(benchmark::kMillisecond)
            ->Iterations(int64_t(frames.size()))
            ->Repetitions(o.repetitions)
            ->ReportAggregatesOnly(true)
            ->UseRealTime();
      }
  int argc = 1;
  char arg0[] = "sdfreel-bench";
  char* argv[] = {arg0, nullptr};
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}

}  // namespace

void add_bench_command(CLI::App& app, int& status) {
  auto o = std::make_shared<BenchOptions>();
  CLI::App* cmd = app.add_subcommand("bench", "seconds per frame per scene, backend and preset");
  cmd->add_option("SCENE", o->scenes, "scenes (default: all)");
  cmd->add_option("--resolution", o->resolution, "WxH of the bench frames")->capture_default_str();
  cmd->add_option("--frames", o->frames, "frames of a 10 s, 30 fps default timeline")
      ->capture_default_str();
  cmd->add_option("--backends", o->backends, "comma-separated: cpu,osmesa")->capture_default_str();
  cmd->add_option("--qualities", o->qualities, "comma-separated presets")->capture_default_str();
  cmd->add_option("--samples", o->samples, "samples per pixel")->capture_default_str();
  cmd->add_option("--repetitions", o->repetitions, "runs of each case; medians are reported")
      ->capture_default_str();
  cmd->add_option("--threads", o->threads, "worker threads (default: all cores)");
  cmd->callback([o, &status] { status = run_bench(*o); });
}

}  // namespace sdfreel
