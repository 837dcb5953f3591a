#pragma once
// The plinths and what stands on them. An exhibit is a function that appends its passes (and
// targets) to the frame plan, drawn with a model transform from exhibit space (origin at the
// centre of the plinth top, +Y up, metres) to the world, into the hall's colour and depth targets
// (so the depth test composites it with the hall). Exhibit 1 is the sdf_morph object; plinths 2
// and 3 hold issue 13's lenticular card and fur (museum/card_exhibit.h, museum/fur_exhibit.h),
// plugged in through ExhibitPasses; exhibit 4 (crepuscular rays) is the air of the whole hall
// (museum/atmosphere.h); its plinth, in the sun before the window, holds a lattice tower of
// the hall's boxes that shows the light (museum/lattice_tower.h).
#include <functional>
#include <glm/glm.hpp>
#include <string>

#include "render/camera_model.h"
#include "render/frame_context.h"
#include "render/frame_plan.h"
#include "scenes/museum/lighting.h"
#include "scenes/museum/probe.h"

namespace sdfreel::museum {

// What a plinth offers its exhibit besides the transform.
struct ExhibitStage {
  const FrameContext& frame;
  const CameraModel& camera;
  const HallLight& light;
  std::string colour;            // the hall's colour target
  std::string depth;             // the hall's depth target
  const ReflectionProbe* probe;  // the hall seen from exhibit 1 (its reflections)
};

using ExhibitPasses =
    std::function<void(FramePlan& plan, const glm::mat4& model, const ExhibitStage& stage)>;

// Exhibit space of plinth i (0..3) onto its top.
glm::mat4 plinth_top(int plinth);

// Exhibit 1's pose on its plinth from the museum's parameters (lift, shift, yaw, scale).
glm::mat4 exhibit_one_model(const FrameContext& ctx);
// The centre of exhibit 1's bound in the world: where its reflection probe is taken.
glm::vec3 exhibit_one_centre(const FrameContext& ctx);

// Appends every exhibit's passes, plinth by plinth; `extra[i]`, when set, hosts plinth i's
// exhibit (MuseumScene::frame_plan sets the card and the fur here).
void add_exhibit_passes(FramePlan& plan, const ExhibitStage& stage,
                        const ExhibitPasses extra[PLINTH_COUNT]);

}  // namespace sdfreel::museum
