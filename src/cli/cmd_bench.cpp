// `sdfreel bench SCENE...`: speed against error. For every scene (a built-in scene's default
// timeline, or a timeline file), backend and configuration (the presets naive, draft and final,
// and a sweep over the march parameters), render the same frames, time them (median of
// repetitions in this process) and compare them with a reference render of the same frames: the
// reference preset with many samples, on the CPU backend, rendered once and cached under
// DIR/reference/ by the timeline's hash and the reference settings. Writes the table to stdout,
// DIR/bench.csv and DIR/bench_<scene>.png (the src/bench/ library does the measuring and drawing).
//
// `sdfreel bench --micro [SCENE...]`: Google Benchmark micro-benchmarks of each scene's distance
// functions, scalar and eight lanes, at fixed points of one frame (src/bench/micro_*); writes the
// table to stdout and DIR/micro.csv.
//
// `sdfreel bench --whole-process SCENE...`: each target rendered end to end by a fresh `sdfreel
// render` on each backend, at the timeline's own size unless --resolution is given
// (cli/bench_whole_process.h); writes the table to stdout and DIR/whole_process.csv.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <limits>
#include <map>
#include <optional>

#include "bench/adaptive_configs.h"
#include "bench/backend_table.h"
#include "bench/csv.h"
#include "bench/median.h"
#include "bench/metrics.h"
#include "bench/micro_bench.h"
#include "bench/micro_report.h"
#include "bench/pareto.h"
#include "bench/plot.h"
#include "bench/reference_cache.h"
#include "bench/shader_configs.h"
#include "bench/sweep.h"
#include "bench/table.h"
#include "cli/bench_io.h"
#include "cli/bench_whole_process.h"
#include "cli/commands_impl.h"
#include "cli/frame_range.h"
#include "scenes/registry.h"
#include "timeline/sha256.h"

namespace sdfreel {

namespace {

using bench::BenchConfig;
using bench::BenchRow;

// The targets for the presets (docs/performance.md, "Speed against error").
constexpr double FINAL_MIN_PSNR_DB = 40.0;
constexpr double DRAFT_MIN_SPEEDUP = 4.0;

struct BenchOptions {
  std::vector<std::string> scenes;
  std::string resolution = "320x180";
  std::string frames = "0-2";
  std::string backends = "cpu";
  std::string out = "output/bench";
  int repetitions = 5;
  int threads = 0;
  bool presets_only = false;
  std::vector<std::string> only;  // name prefixes of the configurations to run
  bool fresh_reference = false;
  bool all_rows = false;
  bool micro = false;
  double micro_min_time = 0.1;  // seconds per repetition of each micro-benchmark
  bool whole_process = false;
  bool resolution_given = false;  // --resolution on the command line (else the default above)
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

// What one bench argument names: a timeline and the frames to render of it.
struct BenchTarget {
  std::string label;  // scene name, or the timeline file's stem
  Timeline tl;
  std::string timeline_hash;
  std::vector<int> frames;
  bool shader = false;  // a user's shader: sample counts on GL, no hit mask (shader_configs.h)
};

BenchTarget load_target(const std::string& arg, const BenchOptions& o) {
  BenchTarget t;
  if (find_scene(arg)) {
    // A scene's default timeline: its defaults, its default camera, 10 s at 30 fps, seed 1.
    t.label = arg;
    t.tl.path = "(bench: " + arg + ")";
    t.tl.scene = arg;
    t.tl.duration = 10.0;
    t.timeline_hash = sha256_hex("sdfreel bench default timeline\nscene=" + arg +
                                 "\nfps=30/1\nduration=10\nseed=1\n");
    int w = 0, h = 0;
    char x = 0, extra = 0;
    if (std::sscanf(o.resolution.c_str(), "%d%c%d%c", &w, &x, &h, &extra) != 3 || x != 'x' ||
        w < 1 || h < 1)
      throw UsageError("--resolution '" + o.resolution + "': expected WxH, e.g. 320x180");
    t.tl.width = w;
    t.tl.height = h;
  } else if (std::filesystem::exists(arg)) {
    RenderOptions ro;
    ro.timeline_path = arg;
    // A whole-process render keeps the timeline's own size unless asked otherwise.
    if (!o.whole_process || o.resolution_given) ro.resolution = o.resolution;
    t.tl = load_with_overrides(ro);
    t.label = std::filesystem::path(arg).stem().string();
    t.timeline_hash = t.tl.sha256;
  } else {
    throw UsageError("'" + arg + "' is neither a scene (see `sdfreel scenes`) nor a timeline file");
  }
  t.frames = parse_frame_list(o.frames, t.tl.frame_count());
  t.shader = t.tl.shader_scene != nullptr;
  return t;
}

// Frame `frame` of the target as `cfg` renders it; `mask`: the hit-mask variant at one sample
// per pixel (the pixel centre), so that hit/miss compares the same ray in both renders.
FrameContext bench_context(const FramePipeline& pipe, int frame, const BenchConfig& cfg,
                           bool mask) {
  FrameContext ctx = frame_context(pipe.timeline(), pipe.scene(), frame);
  ctx.quality = cfg.quality;
  ctx.samples = mask ? 1 : cfg.samples;
  ctx.adaptive = cfg.adaptive;
  ctx.adaptive.enabled = cfg.adaptive.enabled && !mask;
  finish_frame_context(ctx);
  ctx.march = cfg.march;
  ctx.march.hit_mask = mask;
  return ctx;
}

struct Reference {
  std::vector<ImageRGB16> display;
  std::vector<ImageRGBA> mask;
};

// The backend a target's reference renders on: the CPU for a scene; for a user's shader the first
// GL backend asked for, else gl.
std::string reference_backend(const BenchTarget& t, const std::vector<std::string>& backends) {
  if (!t.shader) return "cpu";
  for (const std::string& b : backends)
    if (b != "cpu") return b;
  return "gl";
}

Reference reference_of(const BenchTarget& t, const BenchOptions& o,
                       const std::vector<std::string>& backends) {
  const BenchConfig cfg = t.shader ? bench::shader_reference_config() : bench::reference_config();
  const std::string key =
      bench::reference_key(t.timeline_hash, bench::settings_text(cfg), t.tl.width, t.tl.height);
  const bench::ReferenceCache cache(o.out, key);
  Reference ref;
  std::unique_ptr<FramePipeline> pipe;  // made only when a frame is missing
  for (int frame : t.frames) {
    ImageRGB16 display;
    ImageRGBA mask;
    if (o.fresh_reference || !cache.load(frame, t.tl.width, t.tl.height, display, mask)) {
      if (!pipe)
        pipe = std::make_unique<FramePipeline>(
            t.tl, make_backend(reference_backend(t, backends), o.threads));
      std::fprintf(stderr, "bench: %s reference frame %d (%s, %d samples)\n", t.label.c_str(),
                   frame, cfg.name.c_str(), cfg.samples);
      display = pipe->render_context(bench_context(*pipe, frame, cfg, false)).display;
      // A shader has no hit mask: an empty image of the frame's size keeps the cache's format.
      mask = t.shader ? ImageRGBA(t.tl.width, t.tl.height)
                      : pipe->render_context(bench_context(*pipe, frame, cfg, true)).linear;
      cache.store(frame, display, mask);
    }
    ref.display.push_back(std::move(display));
    ref.mask.push_back(std::move(mask));
  }
  std::fprintf(stderr, "bench: %s reference in %s\n", t.label.c_str(), cache.folder().c_str());
  return ref;
}

// Seconds per frame of one pass over the target's frames.
double time_frames(FramePipeline& pipe, const std::vector<FrameContext>& contexts) {
  double seconds = 0.0;
  for (const FrameContext& ctx : contexts) seconds += pipe.render_context(ctx).seconds;
  return seconds / double(contexts.size());
}

std::vector<FrameContext> bench_contexts(const FramePipeline& pipe, const BenchTarget& t,
                                         const BenchConfig& cfg) {
  std::vector<FrameContext> contexts;
  for (int frame : t.frames) contexts.push_back(bench_context(pipe, frame, cfg, false));
  return contexts;
}

// The errors and the first timed pass of one configuration; run_bench adds the other passes.
BenchRow measure(FramePipeline& pipe, const BenchTarget& t, const std::string& backend,
                 const BenchConfig& cfg, const Reference& ref, std::vector<double>& times) {
  BenchRow row;
  row.scene = t.label;
  row.backend = backend;
  row.preset = cfg.name;
  row.named_preset = cfg.named_preset;
  row.march = cfg.march;
  row.samples = cfg.samples;
  const std::vector<FrameContext> contexts = bench_contexts(pipe, t, cfg);
  bench::ErrorAccumulator error;
  RayStats stats;
  double seconds = 0.0, samples = 0.0;
  for (size_t i = 0; i < contexts.size(); ++i) {
    const RenderedFrame f = pipe.render_context(contexts[i]);
    seconds += f.seconds;
    error.add(f.display, ref.display[i]);
    stats.add(f.stats);
    for (uint16_t n : pipe.backend().sample_counts()) samples += n;
  }
  times.push_back(seconds / double(contexts.size()));
  row.seconds_per_frame = times.back();
  bench::HitMissAccumulator hits;
  if (!t.shader)
    for (size_t i = 0; i < t.frames.size(); ++i)
      hits.add(pipe.render_context(bench_context(pipe, t.frames[i], cfg, true)).linear,
               ref.mask[i]);
  const bench::ErrorMetrics m = error.result();
  row.psnr_db = m.psnr_db;
  row.rmse = m.rmse;
  row.mean_abs_error = m.mean_abs_error;
  row.p99_abs_error = m.p99_abs_error;
  row.hitmiss_fraction = t.shader ? std::numeric_limits<double>::quiet_NaN() : hits.fraction();
  const double pixels = double(t.tl.width) * t.tl.height * double(t.frames.size());
  row.mean_samples = samples / pixels;
  row.sdf_evals_per_pixel = double(stats.sdf_evals) / pixels;
  // Only the CPU backend counts rays that ran out of steps (the shader reports SDF evaluations).
  row.capped_per_pixel =
      backend == "cpu" ? double(stats.capped) / pixels : std::numeric_limits<double>::quiet_NaN();
  return row;
}

void mark_fronts(std::vector<BenchRow>& rows) {
  std::map<std::string, std::vector<size_t>> groups;
  for (size_t i = 0; i < rows.size(); ++i)
    groups[rows[i].scene + "\n" + rows[i].backend].push_back(i);
  for (const auto& [key, idx] : groups) {
    std::vector<bench::SpeedError> pts;
    for (size_t i : idx) pts.push_back({rows[i].seconds_per_frame, rows[i].psnr_db});
    const std::vector<bool> front = bench::pareto_front(pts);
    for (size_t k = 0; k < idx.size(); ++k) rows[idx[k]].on_front = front[k];
  }
}

// The presets' targets, checked on this run's numbers.
void print_preset_check(const std::vector<BenchRow>& rows) {
  std::map<std::string, const BenchRow*> draft, final_;
  for (const BenchRow& r : rows) {
    if (r.preset == "draft") draft[r.scene + " " + r.backend] = &r;
    if (r.preset == "final") final_[r.scene + " " + r.backend] = &r;
  }
  if (!final_.empty())  // a user's shader has no presets
    std::printf("\npreset targets: final >= %.0f dB, draft >= %.0fx faster than final\n",
                FINAL_MIN_PSNR_DB, DRAFT_MIN_SPEEDUP);
  for (const auto& [key, f] : final_) {
    const auto d = draft.find(key);
    const double speedup =
        d != draft.end() ? f->seconds_per_frame / d->second->seconds_per_frame : 0.0;
    std::printf("  %-28s final %6.2f dB %s   draft %5.1fx faster %s\n", key.c_str(), f->psnr_db,
                f->psnr_db >= FINAL_MIN_PSNR_DB ? "ok  " : "MISS", speedup,
                speedup >= DRAFT_MIN_SPEEDUP ? "ok" : "MISS");
  }
  // CPU against llvmpipe, when both ran (docs/performance.md, "CPU against llvmpipe"), and the GL
  // platforms against each other.
  for (const char* gl : {"gl", "egl", "osmesa"}) {
    const std::vector<bench::BackendComparison> cmp = bench::compare_backends(rows, "cpu", gl);
    if (!cmp.empty())
      std::printf("\nCPU against %s (llvmpipe), same presets, same run:\n%s", gl,
                  bench::format_backend_table(cmp, true).c_str());
  }
  const std::vector<bench::BackendComparison> platforms =
      bench::compare_backends(rows, "egl", "osmesa");
  if (!platforms.empty())
    std::printf("\nEGL against OSMesa (both llvmpipe), same presets, same run:\n%s",
                bench::format_backend_table(platforms, false).c_str());
}

// --micro: the frame at video time 4 s of each target (frame 120 at 30 fps; the last frame of a
// shorter timeline), where the default cameras look at the scene's content.
constexpr double MICRO_VIDEO_TIME = 4.0;

bench::MicroTarget micro_target(const BenchTarget& t) {
  const SceneInfo* info = find_scene(t.tl.scene);
  if (!info) throw UsageError("unknown scene '" + t.tl.scene + "'");
  const int frame = std::max(
      0, std::min(int(std::lround(MICRO_VIDEO_TIME * t.tl.fps.value())), t.tl.frame_count() - 1));
  const FrameContext ctx = frame_context(t.tl, *info, frame);
  std::shared_ptr<Scene> scene = info->make();
  scene->prepare(ctx);
  bench::MicroTarget m;
  m.scene = t.label;
  m.owner = scene;
  m.functions = scene->distance_functions();
  m.points =
      bench::camera_sample_points(ctx.camera, bench::MICRO_VIEW_WIDTH, bench::MICRO_VIEW_HEIGHT,
                                  bench::MICRO_MAX_DISTANCE, bench::MICRO_POINT_SEED);
  std::fprintf(stderr, "bench: micro %s frame %d: %zu distance functions, %d points\n",
               t.label.c_str(), frame, m.functions.size(), m.points.size());
  return m;
}

// --only with --micro: the distance functions whose names start with one of the prefixes; a
// prefix that keeps nothing is a usage error naming the functions there are.
void keep_only_functions(std::vector<bench::MicroTarget>& targets,
                         const std::vector<std::string>& only) {
  if (only.empty()) return;
  std::string there;
  for (bench::MicroTarget& t : targets) {
    std::vector<DistanceFunction> keep;
    for (DistanceFunction& fn : t.functions) {
      there += " " + t.scene + "/" + fn.name;
      for (const std::string& prefix : only)
        if (fn.name.rfind(prefix, 0) == 0) {
          keep.push_back(std::move(fn));
          break;
        }
    }
    t.functions = std::move(keep);
  }
  targets.erase(std::remove_if(targets.begin(), targets.end(),
                               [](const bench::MicroTarget& t) { return t.functions.empty(); }),
                targets.end());
  if (targets.empty())
    throw UsageError("--only: no distance function starts with that; there are" + there);
}

int run_micro(const BenchOptions& o) {
  if (o.repetitions < 1) throw UsageError("--repetitions must be at least 1");
  if (!(o.micro_min_time > 0.0)) throw UsageError("--micro-min-time must be positive");
  std::vector<std::string> names = o.scenes;
  if (names.empty())
    for (const SceneInfo& s : all_scenes()) names.push_back(s.name);
  std::vector<bench::MicroTarget> targets;
  for (const std::string& name : names) targets.push_back(micro_target(load_target(name, o)));
  keep_only_functions(targets, o.only);
  std::vector<bench::MicroRow> rows;
  try {
    rows = bench::run_micro_benchmarks(targets, {o.repetitions, o.micro_min_time});
  } catch (const bench::LaneMismatchError& e) {
    throw RenderError(std::string("bench --micro: ") + e.what());
  }
  for (const bench::MicroTarget& t : targets)
    if (t.functions.empty()) std::printf("%s: no distance functions to time\n", t.scene.c_str());
  std::filesystem::create_directories(o.out);
  std::fputs(bench::format_micro_table(rows).c_str(), stdout);
  std::printf("(medians of %d repetitions; %d points per evaluation pass)\n", o.repetitions,
              bench::MICRO_VIEW_WIDTH * bench::MICRO_VIEW_HEIGHT);
  bench::write_micro_csv_file(o.out + "/micro.csv", rows);
  std::printf("csv: %s/micro.csv\n", o.out.c_str());
  return 0;
}

// The samples a target's timeline takes, as the whole-process table shows them.
std::string samples_of(const Timeline& tl) {
  if (!tl.adaptive.enabled) return std::to_string(tl.samples);
  const AdaptiveSampling a = tl.adaptive_at_size();
  return "adaptive " + std::to_string(a.minimum) + ".." + std::to_string(a.maximum);
}

int run_whole(const BenchOptions& o) {
  if (o.scenes.empty())
    throw UsageError("bench --whole-process: name at least one scene or timeline");
  if (o.repetitions < 1) throw UsageError("--repetitions must be at least 1");
  std::filesystem::create_directories(o.out);
  std::vector<WholeProcessTarget> targets;
  for (const std::string& name : o.scenes) {
    const BenchTarget t = load_target(name, o);
    WholeProcessTarget w;
    w.label = t.label;
    if (find_scene(name)) {  // the bench's default timeline of the scene, as a file
      w.timeline_file = write_default_timeline(name, o.out + "/whole-" + name + ".toml");
      w.resolution = o.resolution;
    } else {
      w.timeline_file = name;
      if (o.resolution_given) w.resolution = o.resolution;
    }
    w.frames = int(t.frames.size());
    w.width = t.tl.width, w.height = t.tl.height;
    w.samples = samples_of(t.tl);
    targets.push_back(w);
  }
  return run_whole_process(targets, {split(o.backends), o.frames, o.repetitions, o.out});
}

int run_bench(const BenchOptions& o) {
  if (o.micro) return run_micro(o);
  if (o.whole_process) return run_whole(o);
  if (o.scenes.empty()) throw UsageError("bench: name at least one scene or timeline");
  if (o.repetitions < 1) throw UsageError("--repetitions must be at least 1");
  std::vector<BenchTarget> targets;
  for (const std::string& s : o.scenes) targets.push_back(load_target(s, o));
  const std::vector<std::string> backends = split(o.backends);
  // Every target has the bench's size (load_target): `final` follows it (quality.h).
  std::vector<BenchConfig> configs =
      bench::preset_configs(targets.front().tl.width, targets.front().tl.height);
  if (!o.presets_only)
    for (const BenchConfig& c : bench::sweep_configs())
      if (std::none_of(configs.begin(), configs.end(),
                       [&](const BenchConfig& k) { return bench::same_settings(k, c); }))
        configs.push_back(c);
  // An adaptive point `--only` names outside the sweep is measured too.
  for (const std::string& name : o.only)
    if (const std::optional<BenchConfig> c = bench::adaptive_config_named(name))
      if (std::none_of(configs.begin(), configs.end(),
                       [&](const BenchConfig& k) { return bench::same_settings(k, *c); }))
        configs.push_back(*c);
  // --only: the configurations whose names start with one of its prefixes.
  auto keep_only = [&](std::vector<BenchConfig>& list) {
    if (o.only.empty()) return;
    list.erase(std::remove_if(list.begin(), list.end(),
                              [&](const BenchConfig& c) {
                                return std::none_of(
                                    o.only.begin(), o.only.end(),
                                    [&](const std::string& p) { return c.name.rfind(p, 0) == 0; });
                              }),
               list.end());
  };
  keep_only(configs);
  std::vector<BenchConfig> shader_configs = bench::shader_sample_configs();
  keep_only(shader_configs);
  std::filesystem::create_directories(o.out);

  std::vector<BenchRow> rows;
  std::vector<bench::IoRow> io_rows;
  int failures = 0;
  for (const BenchTarget& t : targets) {
    const Reference ref = reference_of(t, o, backends);
    for (const std::string& asked : backends) {
      // A shader runs on GL only: its `cpu` rows are the reference's GL backend's.
      const std::string backend = t.shader && asked == "cpu" ? reference_backend(t, {}) : asked;
      if (backend != asked && std::count(backends.begin(), backends.end(), backend)) continue;
      const std::vector<BenchConfig>& target_configs = t.shader ? shader_configs : configs;
      std::unique_ptr<FramePipeline> pipe;
      try {
        pipe = std::make_unique<FramePipeline>(t.tl, make_backend(backend, o.threads));
      } catch (const UsageError&) {
        throw;
      } catch (const std::exception& e) {
        std::fprintf(stderr, "bench: skipping %s on %s: %s\n", t.label.c_str(), backend.c_str(),
                     e.what());
        ++failures;
        continue;
      }
      // Errors first, then the timed repetitions as whole passes over every configuration, so
      // that a burst of load from elsewhere on the machine lands on one repetition of many
      // configurations (which the median drops), not on every repetition of one.
      std::vector<const BenchConfig*> measured;
      std::vector<std::vector<double>> times;
      const size_t first = rows.size();
      for (const BenchConfig& cfg : target_configs) {
        try {
          std::vector<double> cfg_times;
          rows.push_back(measure(*pipe, t, backend, cfg, ref, cfg_times));
          measured.push_back(&cfg);
          times.push_back(cfg_times);
          std::fprintf(stderr, "bench: %s %s %-22s %7.2f dB\n", t.label.c_str(), backend.c_str(),
                       cfg.name.c_str(), rows.back().psnr_db);
        } catch (const std::exception& e) {
          std::fprintf(stderr, "bench: skipping %s on %s, %s: %s\n", t.label.c_str(),
                       backend.c_str(), cfg.name.c_str(), e.what());
          ++failures;
        }
      }
      for (int rep = 1; rep < o.repetitions; ++rep) {
        std::fprintf(stderr, "bench: %s %s timing, repetition %d of %d\n", t.label.c_str(),
                     backend.c_str(), rep + 1, o.repetitions);
        for (size_t k = 0; k < measured.size(); ++k)
          times[k].push_back(time_frames(*pipe, bench_contexts(*pipe, t, *measured[k])));
      }
      for (size_t k = 0; k < measured.size(); ++k)
        rows[first + k].seconds_per_frame = bench::median_of(times[k]);
      std::fprintf(stderr, "bench: %s %s start-up and frame writing\n", t.label.c_str(),
                   backend.c_str());
      io_rows.push_back(
          measure_io_row(t.label, t.tl.path, *pipe, backend, t.frames, o.repetitions, o.out));
    }
  }
  mark_fronts(rows);
  std::fputs(bench::format_table(rows, o.all_rows).c_str(), stdout);
  if (!o.all_rows)
    std::printf("(named presets and Pareto-front points; every row is in %s/bench.csv)\n",
                o.out.c_str());
  print_preset_check(rows);
  bench::write_csv_file(o.out + "/bench.csv", rows);
  report_io_rows(io_rows, o.out);
  for (const BenchTarget& t : targets) {
    std::vector<BenchRow> mine;
    for (const BenchRow& r : rows)
      if (r.scene == t.label) mine.push_back(r);
    if (mine.empty()) continue;
    const std::string path = o.out + "/bench_" + t.label + ".png";
    const std::string title = t.label + ": speed against error, " + std::to_string(t.tl.width) +
                              "x" + std::to_string(t.tl.height) + ", " +
                              std::to_string(t.frames.size()) + " frames";
    bench::plot_speed_error(mine, title, path);
    std::printf("plot: %s\n", path.c_str());
  }
  std::printf("csv: %s/bench.csv\n", o.out.c_str());
  return failures && rows.empty() ? 1 : 0;
}

}  // namespace

void add_bench_command(CLI::App& app, int& status) {
  auto o = std::make_shared<BenchOptions>();
  CLI::App* cmd = app.add_subcommand(
      "bench",
      "speed against error of each scene, backend and march preset, with a sweep; or, with "
      "--micro, evaluations per second of each scene's distance functions, scalar and in lanes");
  cmd->add_option("SCENE", o->scenes,
                  "scene names (their default timeline) or timeline files; with --micro, "
                  "optional (default: every scene)");
  cmd->add_option("--resolution", o->resolution, "WxH of the bench frames")->capture_default_str();
  cmd->add_option("--frames", o->frames, "frames to render, e.g. 0-2 or 0,30,60")
      ->capture_default_str();
  cmd->add_option("--backends", o->backends, "comma-separated: cpu,gl,egl,osmesa")
      ->capture_default_str();
  cmd->add_option("--out", o->out, "folder for bench.csv, the plots and the reference cache")
      ->capture_default_str();
  cmd->add_option("--repetitions", o->repetitions,
                  "timed runs of each case (with --micro: of each micro-benchmark); the median is "
                  "kept")
      ->capture_default_str();
  cmd->add_option("--threads", o->threads, "worker threads (default: all cores)");
  cmd->add_option(
         "--only", o->only,
         "run only configurations whose names start with these (with --micro: distance functions)")
      ->delimiter(',');
  cmd->add_flag("--presets-only", o->presets_only, "naive, draft and final only, no sweep");
  cmd->add_flag("--fresh-reference", o->fresh_reference,
                "render the reference again (after a change of scene code)");
  cmd->add_flag("--all", o->all_rows, "print every row, not only presets and the front");
  cmd->add_flag("--micro", o->micro,
                "micro-benchmarks (Google Benchmark): each distance function of each scene, "
                "scalar and eight lanes, at the frame at 4 s, at 2304 points (64x36 camera rays, "
                "seeded distances in [0, 30)); checks lanes == scalar bits first (exit 1 if not); "
                "prints evals/s and writes DIR/micro.csv");
  cmd->add_option("--micro-min-time", o->micro_min_time,
                  "--micro: seconds each repetition of each micro-benchmark runs at least")
      ->capture_default_str();
  cmd->add_flag("--whole-process", o->whole_process,
                "time each target end to end instead: a fresh `sdfreel render TIMELINE --frames F "
                "--no-video` per backend (frames and hashes written), backends alternating, at "
                "the timeline's own size unless --resolution is given; prints each backend's time "
                "against the CPU's and writes DIR/whole_process.csv");
  cmd->callback([o, cmd, &status] {
    o->resolution_given = cmd->count("--resolution") > 0;
    status = run_bench(*o);
  });
}

}  // namespace sdfreel
