#pragma once
// Runs the museum plan's own passes on the CPU, one sample at the pixel centres, into targets a
// test can read: the hall's colour and the depth after the setup passes (the sun's shadow map) and
// the passes named (in plan order), and the sun's shadow map.
#include <set>
#include <string>

#include "scenes/plan_passes.h"

namespace sdfreel::test {

struct MuseumTargets {
  ImageRGBA colour, depth, sun_map;
};

inline MuseumTargets run_museum_passes(const FrameContext& ctx,
                                       const std::set<std::string>& names) {
  CpuTargets targets = run_plan_passes("museum", ctx, names);
  return {targets.get("hall", "test"), targets.get(DEPTH_TARGET, "test"),
          targets.get("sun_shadow", "test")};
}

}  // namespace sdfreel::test
