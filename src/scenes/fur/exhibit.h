#pragma once
// Exhibit 3 of the museum (seed 004): three shapes with shell-textured fur in a case, pushed by the
// timeline and bouncing, the fur trailing their motion. add_exhibit_passes appends its mesh passes
// (the case, then each shape's shells) to a host's plan; the scene "fur" is this exhibit alone,
// and the museum places it on its plinth with its own model matrix.
#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "render/frame_plan.h"
#include "scenes/fur/case_shading.h"
#include "scenes/fur/exhibit_params.h"

namespace sdfreel::fur {

// The key light of the exhibit, in world space (host scenes light the case with the same).
CaseLook exhibit_light(const ExhibitParams& p);

// Lit boxes (instance data = colour) with the exhibit's light and contact shadows: the case, and a
// host's plinth or room.
MeshPass lit_boxes_pass(const std::string& name, std::vector<MeshInstance> boxes,
                        const CaseLook& look);
// The light plus the shapes' contact-shadow discs, in world space.
CaseLook exhibit_look(const glm::mat4& model, const ExhibitParams& p, const ExhibitPose& pose);

// The case's floor is a slab this thick under y = 0: a host stands the case on a surface at
// y = -CASE_FLOOR_THICKNESS, so that no face of the case lies in the host's surface (two
// rasterisers break such a tie differently: streaks of one face or the other).
constexpr float CASE_FLOOR_THICKNESS = 0.04f;

// Appends the case and the three furry shapes in `pose` (exhibit_pose(p.physics, TIME)). `model`
// maps exhibit space (floor of the case at y = 0, centred, interior +-CASE_HALF_X by +-CASE_HALF_Z,
// the open side towards -z) to world space: a rotation, uniform scale and translation.
void add_exhibit_passes(FramePlan& plan, const glm::mat4& model, const ExhibitParams& p,
                        const ExhibitPose& pose);
// The same at scene TIME t (a museum's call: add_exhibit_passes(plan, plinth_top, {}, TIME)).
void add_exhibit_passes(FramePlan& plan, const glm::mat4& model, const ExhibitParams& p, double t);

}  // namespace sdfreel::fur
