#pragma once
// sdf_morph: everything that is constant over one frame, computed once in prepare(). These are
// exactly the uniforms of the GLSL port (shaders/sdf_morph/sdf_morph.glsl): the render functions
// read nothing else besides the named constants in sdf_morph/geometry.h / sdf_morph/render.cpp.
#include <glm/glm.hpp>
#include <vector>

#include "render/frame_context.h"
#include "scenes/scene.h"

namespace sdfreel::sdf_morph {

// A soft-box light of the studio: a rounded rectangle on the plane at unit distance along `dir`
// (gnomonic projection), seen from the object as a bright area in the environment.
struct SoftBox {
  glm::vec3 dir;        // unit, from the object towards the box centre
  glm::vec3 u, v;       // unit, the box's horizontal and vertical axes, both orthogonal to dir
  glm::vec2 half_size;  // half extents on the unit-distance plane
  float corner;         // corner radius on that plane
  glm::vec3 radiance;   // linear Rec.709
};

constexpr int SOFTBOX_COUNT = 3;

struct MorphUniforms {
  // Animation (TIME wrapped in double before it became float).
  float morph = 0.0f;    // 0 = torus, 1 = mug
  float rot_cos = 1.0f;  // world -> object rotation about +Y
  float rot_sin = 0.0f;
  // Scene parameters.
  glm::vec3 base_color{0.9f, 0.6f, 0.3f};
  float reflectivity = 0.6f;   // Schlick F0 of the object
  float key_intensity = 2.0f;  // key light irradiance scale
  float shadow_k = 12.0f;      // penumbra sharpness of the soft shadow
  float env_intensity = 1.0f;  // studio environment scale (walls, soft boxes, ambient)
  // Studio lights; boxes[0] is the key: the direct light comes from its direction.
  SoftBox boxes[SOFTBOX_COUNT];
  // March settings of the frame's quality preset.
  int max_steps = 256;
  int shadow_steps = 64;
  int reflect_steps = 128;
  float hit_eps = 0.25f;  // in pixel footprints (times t * pixel_angle)
  float step_factor = 1.2f;
  float normal_eps = 0.5f;  // in pixel footprints
  float max_dist = 120.0f;
  bool naive = false;     // MarchSettings::naive: world-space epsilons, no bounds, factor 1
  bool hit_mask = false;  // MarchSettings::hit_mask: radiance = hit id (1 object, 2 pedestal)
  int surface = 0;        // MarchSettings::surface: radiance = the hit's distance or normal
};

// Reads TIME, the parameters and the march settings from ctx. ctx.params must hold this scene's
// parameters (ParamValues(&info.params) at least).
MorphUniforms make_morph_uniforms(const FrameContext& ctx);

// The same values for the GLSL twin, named "u_morph.<field>" ("u_morph.boxes[1].dir"); ints are
// passed as floats (the OSMesa driver converts them).
std::vector<ShaderUniform> morph_shader_uniforms(const MorphUniforms& u);

// The morph weight 0..1 at a TIME: a cosine over the period, eased so each shape holds a moment.
float morph_weight(double scene_time, double period);

}  // namespace sdfreel::sdf_morph
