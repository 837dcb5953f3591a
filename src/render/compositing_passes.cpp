#include "render/compositing_passes.h"

namespace sdfreel {

const std::vector<CompositingPass>& compositing_passes() {
  static const std::vector<CompositingPass> passes = {
      {"samples", {"samples"}, "the samples the pixel took (adaptive sampling varies it)"},
      {"sdf_evals",
       {"sdf_evals"},
       "the signed-distance evaluations the pixel cost, all its samples together"},
      {"id", {"id"}, "the scene's number of the surface at the pixel's centre (0: none)"},
      {"depth",
       {"Z"},
       "the distance of the surface at the pixel's centre from the camera's plane (1e10: none)"},
      {"normal",
       {"N.X", "N.Y", "N.Z"},
       "the world-space unit normal of the surface at the pixel's centre (0: none)"},
  };
  return passes;
}

const CompositingPass* find_compositing_pass(const std::string& name) {
  for (const CompositingPass& p : compositing_passes())
    if (p.name == name) return &p;
  return nullptr;
}

}  // namespace sdfreel
