#pragma once
// What the fur exhibit reads from the timeline: one look per fur and the physics inputs. The
// default-constructed values are the scene's parameter defaults (fur.cpp builds its ParamSpecs
// from them), so a host scene such as the museum can start from ExhibitParams{}.
#include <array>
#include <string>
#include <vector>

#include "render/params.h"
#include "scenes/fur/physics.h"

namespace sdfreel::fur {

// One fur's shell texturing (parameters `<prefix>_<name>`).
struct FurLook {
  double length = 0.05;    // shell extrusion of the outermost shell, exhibit units (m)
  double density = 100.0;  // strand cells per UV unit
  double thickness = 1.5;  // strand radius at the root, in half cells
  double curvature = 1.0;  // k = h^(1 + curvature): how much the tips bend more than the roots
  glm::dvec3 base_color{0.1, 0.05, 0.03}, tip_color{0.7, 0.5, 0.3};  // linear Rec.709
  double shells = 16.0;                                              // shell count N
};

struct ExhibitParams {
  std::array<FurLook, BODY_COUNT> looks = default_looks();
  PhysicsInputs physics{};
  double displacement_strength = 0.35;  // scales the spring's lag on the tips
  double light_intensity = 1.6;         // the key light
  bool hit_mask = false;     // MarchSettings::hit_mask: colour = hit id (0, or 1 + shape index)
  float hit_id_base = 0.0f;  // added to the shapes' ids (a host scene keeps its own apart)
  int surface = 0;           // MarchSettings::surface: the surface's distance or normal instead
  glm::vec3 eye{0.0f};       // the camera's origin, which that distance is measured from
  static std::array<FurLook, BODY_COUNT> default_looks();
};

constexpr const char* FUR_PREFIXES[BODY_COUNT] = {"sphere", "cube", "torus"};

// The parameters' names start with `prefix` (the museum names its exhibit's `fur_...`).
std::vector<ParamSpec> exhibit_param_specs(const std::string& prefix = "");
ExhibitParams read_exhibit_params(const ParamValues& v, const std::string& prefix = "");

}  // namespace sdfreel::fur
