// water_lily: the per-frame constants, the twin of src/scenes/water_lily/uniforms.h. The C++
// scene computes them in prepare() and hands them over through shader_uniforms() as u_lily.<field>.
#include "water_lily/layout.glsl"

struct LilyUniforms {
  float curl[FLOWER_COUNT];
  float petal_lipschitz[PETAL_LAYERS];
  float leaf_lipschitz[LEAF_COUNT];
  vec2 drift_offset;
  float water_time_a;
  float water_time_b;
  float water_blend;
  float cloud_shift;
  vec3 sun_dir;
  vec3 sun_color;
  vec3 fill_dir;
  float water_bump;
  float translucency;
  float droplets;
  float contrast;
  float saturation;
  float vignette;
  float fog_distance;
  float shadow_k;
  vec3 cam_right;
  vec3 cam_up;
  vec3 cam_forward;
  float inv_tan_half_fov;
  float inv_aspect;
  int max_steps;
  int shadow_steps;
  int reflect_steps;
  float hit_eps;
  float step_factor;
  float normal_eps;
  float max_dist;
  int naive;     // MarchSettings::naive (0 or 1)
  int hit_mask;  // MarchSettings::hit_mask (0 or 1)
  int surface;   // MarchSettings::surface (common/surface_output.glsl)
};
