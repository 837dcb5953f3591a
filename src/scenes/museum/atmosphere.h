#pragma once
// Exhibit 4 and the hall's air, as image passes after the hall and exhibits are drawn:
// - occlusion: 1 where depth is still cleared (nothing drawn: the sky through the window), else 0,
//   the seed's `depth <= 0` trick (reversed-Z there, z_w = 1 here);
// - crepuscular rays over it (src/render/passes/crepuscular_rays.h: seed 004's loop, 128 taps
//   decaying towards the pixel's end of the shaft, integer-hash jitter, border stop, fade when
//   the sun leaves the view or is behind the camera);
// - composite: the hall, fogged, plus the rays in the sun's colour. The fog stands in for Godot's
//   volumetric fog: exponential distance fog (extinction 1 - exp(-sigma d), written as the
//   rational 1 - 1 / (1 + x + x^2 / 2) to stay in plain arithmetic on both backends) whose colour
//   is ambient plus a forward-scattering lobe towards the sun, (max(cos, 0))^16.
// The GLSL twins are shaders/museum/occlusion.glsl and shaders/museum/composite.glsl.
#include <glm/glm.hpp>
#include <string>

#include "render/camera_model.h"
#include "render/frame_context.h"
#include "render/frame_plan.h"

namespace sdfreel::museum {

struct Atmosphere {
  float fog_density = 0.02f;  // sigma, per metre
  float rays_strength = 0.7f;
};

// An image pass copying `from` to `to` (the hit-mask frame: the ids without air).
ImagePass copy_pass(const std::string& from, const std::string& to);

// Appends the occlusion, rays and composite passes: `scene` and DEPTH_TARGET in, COLOUR_TARGET out.
void add_atmosphere_passes(FramePlan& plan, const Atmosphere& a, const FrameContext& ctx,
                           const CameraModel& cam, const std::string& scene);

}  // namespace sdfreel::museum
