// mesh_method_bench: the CPU backend's rasteriser against Intel Embree's ray casting for the
// museum's mesh passes (docs/mesh-method.md). For each case, frame size and sample count it finds
// the nearest kept triangle of every sample both ways, prints the median times of several runs side
// by side and how far the two agree, then checks that each method's results are bit-stable across
// thread counts. Built only with -DSDFREEL_WITH_EMBREE=ON (tools/mesh_method_bench/CMakeLists.txt).
//
//   mesh_method_bench [--runs N] [--threads N] [--quality low|medium] [--cases hall,fur,museum]
//                     [--sizes 320x180,1280x720] [--spp 1,2,4]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "agreement.h"
#include "bench_case.h"
#include "embree_ids.h"
#include "raster_ids.h"

using namespace sdfreel;
using namespace sdfreel::mesh_bench;

namespace {

struct Options {
  int runs = 5, threads = 1;
  RTCBuildQuality quality = RTC_BUILD_QUALITY_MEDIUM;
  std::vector<std::string> cases{"hall", "fur", "museum"};
  std::vector<std::pair<int, int>> sizes{{320, 180}, {1280, 720}};
  std::vector<int> spp{1, 2, 4};
};

std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream in(s);
  for (std::string item; std::getline(in, item, ',');) out.push_back(item);
  return out;
}

constexpr const char* USAGE =
    "usage: mesh_method_bench [--runs N] [--threads N] [--quality low|medium] "
    "[--cases hall,fur,museum] [--sizes 320x180,1280x720] [--spp 1,2,4]";

[[noreturn]] void usage(const std::string& why) {
  std::fprintf(stderr, "mesh_method_bench: %s\n%s\n", why.c_str(), USAGE);
  std::exit(2);
}

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--help" || a == "-h") {
      std::printf("%s\n", USAGE);
      std::exit(0);
    }
    if (i + 1 >= argc) usage("missing value after " + a);
    const std::string v = argv[++i];
    if (a == "--runs") {
      o.runs = std::max(1, std::atoi(v.c_str()));
    } else if (a == "--threads") {
      o.threads = std::max(0, std::atoi(v.c_str()));
    } else if (a == "--quality") {
      if (v != "low" && v != "medium") usage("--quality is low or medium");
      o.quality = v == "low" ? RTC_BUILD_QUALITY_LOW : RTC_BUILD_QUALITY_MEDIUM;
    } else if (a == "--cases") {
      o.cases = split(v);
    } else if (a == "--sizes") {
      o.sizes.clear();
      for (const std::string& s : split(v)) {
        int w = 0, h = 0;
        if (std::sscanf(s.c_str(), "%dx%d", &w, &h) != 2 || w < 1 || h < 1) usage("bad size " + s);
        o.sizes.push_back({w, h});
      }
    } else if (a == "--spp") {
      o.spp.clear();
      for (const std::string& s : split(v)) o.spp.push_back(std::max(1, std::atoi(s.c_str())));
    } else {
      usage("unknown option " + a);
    }
  }
  return o;
}

// Median wall time of `runs` calls, in milliseconds.
double median_ms(int runs, const std::function<void()>& fn) {
  std::vector<double> ms;
  for (int r = 0; r < runs; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    fn();
    ms.push_back(
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
  }
  std::sort(ms.begin(), ms.end());
  return ms.size() % 2 ? ms[ms.size() / 2] : 0.5 * (ms[ms.size() / 2 - 1] + ms[ms.size() / 2]);
}

CaseSpec find_spec(const std::string& name) {
  for (const CaseSpec& s : standard_cases())
    if (s.name == name) return s;
  usage("unknown case " + name);
}

void measure(const CaseSpec& spec, int w, int h, int spp, const Options& o) {
  const BenchCase c = make_case(spec, w, h, spp);
  FlatTriangles flat = flatten(c);
  const double vertex_ms = median_ms(o.runs, [&] { flat = flatten(c); });
  const RasterIds raster(c, flat);
  EmbreeIds embree(o.threads, o.quality);
  SampleHits scene_hits(0, 0, 0), raster_hits(0, 0, 0), ray1(0, 0, 0), ray8(0, 0, 0);
  const double scene_ms = median_ms(o.runs, [&] { scene_hits = run_scene_passes(c, o.threads); });
  const double raster_ms = median_ms(o.runs, [&] { raster_hits = raster.run(o.threads); });
  const double build_ms = median_ms(o.runs, [&] { embree.build(c, flat); });
  const double trace1_ms = median_ms(o.runs, [&] { ray1 = embree.trace(o.threads, false); });
  const double trace8_ms = median_ms(o.runs, [&] { ray8 = embree.trace(o.threads, true); });
  const Agreement g = compare(raster_hits, ray1, c.camera);
  const Agreement packets = compare(ray1, ray8, c.camera);
  const double embree_ms = build_ms + std::min(trace1_ms, trace8_ms);
  std::printf(
      "| %s | %dx%d | %d | %zu | %.2f | %.2f | %.2f | %.2f | %.2f | %.2f | %.2f | %.2f | %.4f%% | "
      "%zu | %zu | %zu | %.1e | %s | %zu |\n",
      c.name.c_str(), w, h, spp, flat.count(), vertex_ms, scene_ms, raster_ms, build_ms, trace1_ms,
      trace8_ms, embree_ms, embree_ms / raster_ms, 100.0 * g.same_fraction(), g.hit_vs_miss, g.tie,
      g.other, g.max_depth_diff, same_depth_bits(scene_hits, raster_hits) ? "yes" : "NO",
      packets.samples - packets.same);
  std::fflush(stdout);
}

// Bit-stability across thread counts: Embree's BVH built on 1 and on 2 threads (and traced on as
// many), the rasteriser on 1 and 2 threads, each compared with itself.
void determinism(const CaseSpec& spec, int w, int h, int spp, RTCBuildQuality quality) {
  const BenchCase c = make_case(spec, w, h, spp);
  const FlatTriangles flat = flatten(c);
  const RasterIds raster(c, flat);
  const bool raster_same = bit_identical(raster.run(1), raster.run(2));
  EmbreeIds one(1, quality), two(2, quality);
  one.build(c, flat);
  const SampleHits a = one.trace(1, false);
  bool embree_same = true, rebuild_same = true;
  for (int r = 0; r < 3; ++r) {
    two.build(c, flat);
    embree_same = embree_same && bit_identical(a, two.trace(2, false));
    one.build(c, flat);
    rebuild_same = rebuild_same && bit_identical(a, one.trace(1, false));
  }
  std::printf("| %s | %dx%d | %d | %s | %s | %s |\n", c.name.c_str(), w, h, spp,
              raster_same ? "yes" : "NO", rebuild_same ? "yes" : "NO", embree_same ? "yes" : "NO");
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  const Options o = parse(argc, argv);
  std::vector<CaseSpec> specs;
  for (const std::string& name : o.cases) specs.push_back(find_spec(name));
  std::printf(
      "Median of %d runs, %d thread(s), Embree build quality %s, milliseconds per frame (all "
      "samples).\n\n",
      o.runs, o.threads, o.quality == RTC_BUILD_QUALITY_LOW ? "low" : "medium");
  std::printf("%s\n\n", EmbreeIds(o.threads, o.quality).describe().c_str());
  std::printf(
      "| case | frame | spp | triangles | vertex stage | raster: scene's passes | raster: ids | "
      "Embree build | Embree trace x1 | Embree trace x8 | Embree build + trace | Embree / raster | "
      "same triangle | hit vs miss | ties | other | max dz_w same tri | ids = scene depth | x1 != "
      "x8 |\n|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (const CaseSpec& spec : specs)
    for (const auto& [w, h] : o.sizes)
      for (int spp : o.spp) measure(spec, w, h, spp, o);
  std::printf(
      "\nBit-identical results across threads (rasteriser 1 vs 2 threads; Embree rebuilt 3 times "
      "on 1 thread; Embree built and traced on 2 threads vs 1):\n\n| case | frame | spp | "
      "raster 1 = 2 | Embree rebuild = | Embree 2 = 1 |\n|---|---|---|---|---|---|\n");
  for (const CaseSpec& spec : specs)
    determinism(spec, o.sizes.front().first, o.sizes.front().second, o.spp.back(), o.quality);
  return 0;
}
