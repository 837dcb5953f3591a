#pragma once
// water_lily: everything that is constant over one frame, computed once in prepare(). These are
// exactly the uniforms of the GLSL twin (shaders/water_lily/uniforms.glsl): the render functions
// read nothing else besides the named constants in layout.h and render.cpp.
#include <glm/glm.hpp>
#include <vector>

#include "render/frame_context.h"
#include "scenes/scene.h"
#include "scenes/water_lily/layout.h"

namespace sdfreel::water_lily {

struct LilyUniforms {
  // Animation (phases wrapped in double before they became floats).
  float curl[FLOWER_COUNT];  // petal curl rate (radians per unit of petal length), per flower
  // Lipschitz bounds of the reshaped parts at this frame's curls: each petal layer's distance
  // is divided by its bound (geometry.h); the naive preset multiplies by NAIVE_PETAL_FACTOR.
  float petal_lipschitz[PETAL_LAYERS];
  float leaf_lipschitz[LEAF_COUNT];
  glm::vec2 drift_offset{0};  // the drifting leaf's displacement in x and z
  float water_time_a = 0;     // the water's 3D FBM time coordinate ...
  float water_time_b = 0;     // ... and its wrapped twin, blended in by water_blend near the wrap
  float water_blend = 0;      // 0: only a; 1: only b
  float cloud_shift = 0;      // slow sky drift
  // Look.
  glm::vec3 sun_dir{0, 1, 0};  // unit, towards the sun
  glm::vec3 sun_color{1};
  glm::vec3 fill_dir{0, 1, 0};  // unit, the sky's fill light
  float water_bump = 1;
  float translucency = 0.5f;
  float droplets = 1.0f;  // scales the share of grid cells with a water drop (droplets.h)
  float contrast = 0.3f;
  float saturation = 1.1f;
  float vignette = 0.45f;
  float fog_distance = 30;
  float shadow_k = 8;
  // The camera, for the vignette: screen position of a ray direction.
  glm::vec3 cam_right{1, 0, 0}, cam_up{0, 1, 0}, cam_forward{0, 0, 1};
  float inv_tan_half_fov = 1;
  float inv_aspect = 1;
  // March settings of the frame's quality preset.
  int max_steps = 256;
  int shadow_steps = 64;
  int reflect_steps = 128;
  float hit_eps = 0.25f;
  float step_factor = 1.2f;
  float normal_eps = 0.5f;
  float max_dist = 120.0f;
  bool naive = false;
  bool hit_mask = false;
  int surface = 0;  // MarchSettings::surface: radiance = the hit's distance or normal
};

// Reads TIME, the parameters, the camera and the march settings from ctx.
LilyUniforms make_lily_uniforms(const FrameContext& ctx);

// The same values for the GLSL twin, named "u_lily.<field>" (arrays "u_lily.curl"); ints and
// bools are passed as floats.
std::vector<ShaderUniform> lily_shader_uniforms(const LilyUniforms& u);

}  // namespace sdfreel::water_lily
