#include "render/frame_plan.h"

namespace sdfreel {

std::vector<TargetSpec> plan_targets(const FramePlan& plan) {
  std::vector<TargetSpec> t = {{COLOUR_TARGET, TargetKind::Colour, glm::vec4(0.0f)},
                               {DEPTH_TARGET, TargetKind::Depth, glm::vec4(1.0f)},
                               {SDF_EVALS_TARGET, TargetKind::Colour, glm::vec4(0.0f)}};
  t.insert(t.end(), plan.targets.begin(), plan.targets.end());
  return t;
}

const std::string& pass_name(const Pass& pass) {
  return std::visit([](const auto& p) -> const std::string& { return p.name; }, pass);
}

}  // namespace sdfreel
