#pragma once
// Method (b), Intel Embree 3 (Debian's libembree-dev): primary rays through the same sample
// positions as the ray passes trace, against a BVH of the same flattened triangles.
//
// GL's rules on top of Embree: culling is decided per triangle when the scene is built (every
// primary ray starts at the eye, so a triangle faces all of them the same way: the sign of
// dot(cross(v1 - v0, v2 - v0), eye - v0), which is the sign of its window-space area); alpha
// discard is an intersection filter that runs the scene's shading at the candidate hit and
// rejects it below the cutoff; the near and far planes bound the ray's t. Edges follow Embree's
// own (watertight with RTC_SCENE_FLAG_ROBUST) test, not GL's top-left rule: the agreement counts
// tell what that changes.
#include <embree3/rtcore.h>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "bench_case.h"
#include "sample_hits.h"

namespace sdfreel::mesh_bench {

// Alpha tests (the filter's calls of the scene's shading) since the last call, all threads.
uint64_t take_embree_alpha_tests();

class EmbreeIds {
 public:
  // threads: Embree's build threads (0 = all cores); quality: RTC_BUILD_QUALITY_LOW (Morton
  // codes, Embree's choice for scenes rebuilt every frame) or _MEDIUM (binned SAH, its default).
  // isa: "" (Embree picks the widest the CPU has) or one Embree must use ("sse2", "avx2"...).
  EmbreeIds(int threads, RTCBuildQuality quality, const std::string& isa = "");
  ~EmbreeIds();
  EmbreeIds(const EmbreeIds&) = delete;
  EmbreeIds& operator=(const EmbreeIds&) = delete;

  // A new BVH of `flat` (the frame's triangles: built once per frame, since meshes move).
  void build(const BenchCase& c, const FlatTriangles& flat);
  // Every sample of every pixel: one ray at a time (rtcIntersect1) or eight pixels of a row at a
  // time (rtcIntersect8), tiles spread over `threads`.
  SampleHits trace(int threads, bool packets) const;

  // Embree's build: version, whether eight-wide packets are native, its tasking system.
  std::string describe() const;

  struct PassGeometry;  // per pass: its triangles' ids and what the alpha filter needs

 private:
  void release_scene();
  RTCDevice device_ = nullptr;
  RTCBuildQuality quality_;
  RTCScene scene_ = nullptr;
  const BenchCase* case_ = nullptr;
  std::vector<std::unique_ptr<PassGeometry>> geometries_;
};

}  // namespace sdfreel::mesh_bench
