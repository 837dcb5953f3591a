#pragma once
// Method (a), the CPU backend's own rasteriser, through its public entry point run_mesh_pass.
//
// The scene's passes carry no triangle ids, so each becomes an id pass: its flattened world-space
// triangles as one mesh with an identity instance (the same position bits, so the same coverage
// and depth), the id in the normal, which the rasteriser interpolates as a constant. Passes with
// alpha discard (fur shells) still call the scene's own shading for alpha, with the instance data
// and uv of the original triangle (shell alpha reads nothing else).
#include <cstdint>
#include <memory>

#include "bench_case.h"
#include "sample_hits.h"

namespace sdfreel::mesh_bench {

class RasterIds {
 public:
  RasterIds(const BenchCase& c, const FlatTriangles& flat);
  SampleHits run(int threads) const;

 private:
  const BenchCase& case_;
  std::vector<MeshPass> id_passes_;
};

// Alpha tests (the scene's shading called for a shell fragment) since the last call, all threads.
uint64_t take_raster_alpha_tests();

// The scene's own passes with their own vertex stage and shading, as the renderer draws them: the
// time of the real thing, and the depth the id passes must reproduce (ids stay 0).
SampleHits run_scene_passes(const BenchCase& c, int threads);

}  // namespace sdfreel::mesh_bench
