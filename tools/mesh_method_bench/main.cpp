// mesh_method_bench: the CPU backend's rasteriser against Intel Embree's ray casting for the
// museum's mesh passes (docs/mesh-method.md). For each case, frame size and sample count it finds
// the nearest kept triangle of every sample both ways, prints the median times of several runs side
// by side and how far the two agree, then checks that each method's results are bit-stable across
// thread counts. Built only with -DSDFREEL_WITH_EMBREE=ON (tools/mesh_method_bench/CMakeLists.txt).
//
//   mesh_method_bench [--runs N] [--threads N] [--quality low|medium] [--cases hall,fur,museum]
//                     [--sizes 320x180,1280x720] [--spp 1,2,4] [--images DIR]
#include <algorithm>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include "agreement.h"
#include "bench_case.h"
#include "embree_ids.h"
#include "id_images.h"
#include "options.h"
#include "raster_ids.h"
#include "timing.h"

using namespace sdfreel;
using namespace sdfreel::mesh_bench;

namespace {

// Medians over interleaved rounds (every method once per round, after one untimed round), so a
// change of load on a shared machine hits all methods alike.
enum Step { VERTEX, SCENE, RASTER, BUILD, TRACE1, TRACE8, STEPS };

std::vector<std::string> wall_rows;

void measure(const CaseSpec& spec, int w, int h, int spp, const Options& o) {
  const BenchCase c = make_case(spec, w, h, spp);
  FlatTriangles flat = flatten(c);
  const RasterIds raster(c, flat);
  EmbreeIds embree(o.threads, o.quality);
  SampleHits scene_hits(0, 0, 0), raster_hits(0, 0, 0), ray1(0, 0, 0), ray8(0, 0, 0);
  const std::function<void()> steps[STEPS] = {[&] { flat = flatten(c); },
                                              [&] { scene_hits = run_scene_passes(c, o.threads); },
                                              [&] { raster_hits = raster.run(o.threads); },
                                              [&] { embree.build(c, flat); },
                                              [&] { ray1 = embree.trace(o.threads, false); },
                                              [&] { ray8 = embree.trace(o.threads, true); }};
  std::vector<double> cpu[STEPS], wall[STEPS];
  uint64_t alpha_tests[STEPS] = {};
  for (int r = -1; r < o.runs; ++r)
    for (int k = 0; k < STEPS; ++k) {
      take_raster_alpha_tests(), take_embree_alpha_tests();
      const Elapsed e = time_call(steps[k]);
      alpha_tests[k] = take_raster_alpha_tests() + take_embree_alpha_tests();
      if (r < 0) continue;
      cpu[k].push_back(e.cpu_ms);
      wall[k].push_back(e.wall_ms);
    }
  double ms[STEPS], wall_ms[STEPS];
  for (int k = 0; k < STEPS; ++k) ms[k] = median(cpu[k]), wall_ms[k] = median(wall[k]);
  std::vector<bool> alpha_pass(flat.count());
  for (size_t t = 0; t < flat.count(); ++t)
    alpha_pass[t] = c.passes[flat.pass_of[t]].alpha_cutoff > 0.0f;
  const Agreement g = compare(raster_hits, ray1, c.camera, alpha_pass);
  const double embree_ms = ms[BUILD] + std::min(ms[TRACE1], ms[TRACE8]);
  std::printf(
      "| %s | %dx%d | %d | %zu | %.1f | %.1f | %.1f | %.1f | %.1f | %.1f | %.1f | %.2f | %.4f%% | "
      "%zu | %zu | %zu | %zu | %.1e | %s | %zu |\n",
      c.name.c_str(), w, h, spp, flat.count(), ms[VERTEX], ms[SCENE], ms[RASTER], ms[BUILD],
      ms[TRACE1], ms[TRACE8], embree_ms, embree_ms / ms[RASTER], 100.0 * g.same_fraction(),
      g.hit_vs_miss, g.tie, g.other, g.other_alpha, g.max_depth_diff,
      same_depth_bits(scene_hits, raster_hits) ? "yes" : "NO", differing_samples(ray1, ray8));
  std::fflush(stdout);
  if (!o.images.empty())
    write_id_images(o.images,
                    c.name + "_" + std::to_string(w) + "x" + std::to_string(h) + "_" +
                        std::to_string(spp) + "spp",
                    raster_hits, ray1, c.camera);
  const double wall_embree = wall_ms[BUILD] + std::min(wall_ms[TRACE1], wall_ms[TRACE8]);
  const double samples = double(raster_hits.id.size());
  char row[256];
  std::snprintf(row, sizeof row, "| %s | %dx%d | %d | %.1f | %.1f | %.1f | %.2f | %.2f | %.2f |\n",
                c.name.c_str(), w, h, spp, wall_ms[SCENE], wall_ms[RASTER], wall_embree,
                wall_embree / wall_ms[RASTER], double(alpha_tests[RASTER]) / samples,
                double(alpha_tests[TRACE1]) / samples);
  wall_rows.push_back(row);
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
  // Embree picks its kernels by the CPU it runs on: the same build on another machine may use
  // others. Forced narrower ones stand in for such a machine.
  std::string isa_same;
  for (const char* isa : {"sse2", "sse4.2", "avx"}) {
    EmbreeIds narrow(1, quality, isa);
    narrow.build(c, flat);
    const SampleHits b = narrow.trace(1, false);
    const Agreement g = compare(a, b, c.camera);
    isa_same += std::string(isa_same.empty() ? "" : ", ") + isa + " " +
                std::to_string(differing_samples(a, b)) + " (ids " +
                std::to_string(g.samples - g.same) + ")";
  }
  std::printf("| %s | %dx%d | %d | %s | %s | %s | %s |\n", c.name.c_str(), w, h, spp,
              raster_same ? "yes" : "NO", rebuild_same ? "yes" : "NO", embree_same ? "yes" : "NO",
              isa_same.c_str());
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  const Options o = parse_options(argc, argv);
  std::vector<CaseSpec> specs;
  for (const std::string& name : o.cases) specs.push_back(find_spec(name));
  std::printf(
      "Median of %d interleaved runs, %d thread(s), Embree build quality %s; process CPU "
      "milliseconds per frame (all samples, all threads).\n\n",
      o.runs, o.threads, o.quality == RTC_BUILD_QUALITY_LOW ? "low" : "medium");
  std::printf("%s\n\n", EmbreeIds(o.threads, o.quality).describe().c_str());
  std::printf(
      "| case | frame | spp | triangles | vertex stage | raster: scene's passes | raster: ids | "
      "Embree build | Embree trace x1 | Embree trace x8 | Embree build + trace | Embree / raster | "
      "same triangle | hit vs miss | ties | other | of which both alpha | max dz_w same tri | ids "
      "= scene depth | x1 != "
      "x8 |\n|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (const CaseSpec& spec : specs)
    for (const auto& [w, h] : o.sizes)
      for (int spp : o.spp) measure(spec, w, h, spp, o);
  std::printf(
      "\nThe same, wall milliseconds; and alpha tests (calls of the scene's shading for a fragment "
      "or "
      "candidate hit of a pass with alpha discard) per sample:\n\n| case | frame | spp | raster: "
      "scene's passes | raster: ids | Embree build + trace | Embree / raster | alpha tests: raster "
      "| alpha tests: Embree x1 |\n|---|---|---|---|---|---|---|---|---|\n");
  for (const std::string& row : wall_rows) std::printf("%s", row.c_str());
  std::printf(
      "\nBit-identical results across threads (rasteriser 1 vs 2 threads; Embree rebuilt 3 times "
      "on 1 thread; Embree built and traced on 2 threads vs 1):\n\n| case | frame | spp | "
      "raster 1 = 2 | Embree rebuild = | Embree 2 = 1 | samples (ids) that differ from Embree's "
      "default "
      "(avx2) "
      "kernels |\n|---|---|---|---|---|---|---|\n");
  for (const CaseSpec& spec : specs)
    determinism(spec, o.sizes.front().first, o.sizes.front().second, o.spp.back(), o.quality);
  return 0;
}
