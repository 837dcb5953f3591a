// sdf_morph: the per-frame constants, the twin of src/scenes/sdf_morph/uniforms.h. The C++ scene
// computes them in prepare() and hands them over through shader_uniforms() as u_morph.<field>.

struct SoftBox {
  vec3 dir;
  vec3 u, v;
  vec2 half_size;
  float corner;
  vec3 radiance;
};

const int SOFTBOX_COUNT = 3;

struct MorphUniforms {
  float morph;
  float rot_cos;
  float rot_sin;
  vec3 base_color;
  float reflectivity;
  float key_intensity;
  float shadow_k;
  float env_intensity;
  SoftBox boxes[SOFTBOX_COUNT];
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
