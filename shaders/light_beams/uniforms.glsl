// light_beams: the per-frame constants, the twin of src/scenes/light_beams/uniforms.h. The C++
// scene computes them in prepare() and hands them over through shader_uniforms() as
// u_beams.<field>.

const int LIGHT_COUNT = 4;
const int BEAM_COUNT = 4;
const int OCCLUDER = LIGHT_COUNT + BEAM_COUNT;
const int SHAPE_COUNT = OCCLUDER + 1;
const int MAX_PAIR_CROSSINGS = 8;
const int MAX_CROSSINGS = 64;
const int PAIR_CROSSING = 0;
const int PAIR_APART = 1;
const int PAIR_FIRST_INSIDE = 2;
const int PAIR_SECOND_INSIDE = 3;

const int ESTIMATOR_SEED_RAY = 0;
const int ESTIMATOR_PENUMBRA = 1;
const int ESTIMATOR_EXACT = 2;

struct BeamsUniforms {
  Shape shapes[SHAPE_COUNT];
  vec3 color[SHAPE_COUNT];
  float gain[SHAPE_COUNT];
  float fades[SHAPE_COUNT];
  float glow_constant, glow_linear, glow_quadratic;
  vec3 background;
  int estimator;
  int shadow_steps;
  float min_hit_dist;
  float max_trace_dist;
  int hit_mask;
  vec2 crossings[MAX_CROSSINGS];
  int crossing_first[SHAPE_COUNT * SHAPE_COUNT + 1];
  int pair_mode[SHAPE_COUNT * SHAPE_COUNT];
  vec4 pair_line[SHAPE_COUNT * SHAPE_COUNT];
};

uniform BeamsUniforms u_beams;

// Whether shape j stands in the light of the others (castsShadow in uniforms.h): the occluder and
// every light that shines; a beam flickered fully out is gone.
bool castsShadow(int j) { return j == OCCLUDER || u_beams.gain[j] > 0.0; }
