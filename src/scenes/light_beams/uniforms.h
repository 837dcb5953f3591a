#pragma once
// light_beams: everything constant over one frame, computed once in prepare(): the shapes where
// TIME put them, each light's colour and gain (flicker included), the glow and the estimator of
// the frame's preset. Exactly the uniforms of the GLSL twin (shaders/light_beams/uniforms.glsl).
#include <glm/glm.hpp>
#include <vector>

#include "render/frame_context.h"
#include "scenes/light_beams/shapes.h"
#include "scenes/scene.h"

namespace sdfreel::light_beams {

// Four glowing shapes, four vertical beams, one occluder.
constexpr int LIGHT_COUNT = 4;
constexpr int BEAM_COUNT = 4;
constexpr int FIRST_BEAM = LIGHT_COUNT;
constexpr int OCCLUDER = LIGHT_COUNT + BEAM_COUNT;
constexpr int SHAPE_COUNT = OCCLUDER + 1;
// Crossings of two shapes' outlines (crossings.h): two stadiums cross in at most 8 points.
constexpr int MAX_PAIR_CROSSINGS = 8;
constexpr int MAX_CROSSINGS = 64;
// How two shapes i < j lie (crossings.h), which says which one a ray meets first.
constexpr int PAIR_CROSSING = 0;       // outlines cross (or undecided): cut and test rays
constexpr int PAIR_APART = 1;          // disjoint: the side of a separating line decides
constexpr int PAIR_FIRST_INSIDE = 2;   // i inside j: j always first
constexpr int PAIR_SECOND_INSIDE = 3;  // j inside i: i always first

// How a pixel finds how much of a light it sees (docs/scenes/light_beams.md, "Figures").
enum Estimator {
  // The seed's shadow: one ray marched toward the light's closest point, lit or not.
  ESTIMATOR_SEED_RAY = 0,
  // Each occluder's covered share of the light's angular span, multiplied: exact for a single
  // occluder (a circle or a capsule, of any size, overlapping the light or not), too dark only
  // where several occluders hide the same angles.
  ESTIMATOR_PENUMBRA = 1,
  // The unblocked share of the span in closed form: the union of the angles where an occluder
  // comes before the light.
  ESTIMATOR_EXACT = 2,
};

struct BeamsUniforms {
  Shape shapes[SHAPE_COUNT];
  glm::vec3 color[SHAPE_COUNT];  // glow colour, linear Rec.709
  float gain[SHAPE_COUNT];       // HDR scale of core and glow, flicker included; 0: not a light
  float fades[SHAPE_COUNT];      // 1: the glow fades toward the frame's corners (the beams)
  float glow_constant = 1.0f, glow_linear = 12.0f, glow_quadratic = 150.0f;
  glm::vec3 background{0.01f, 0.02f, 0.05f};
  int estimator = ESTIMATOR_PENUMBRA;
  // The seed's march (ESTIMATOR_SEED_RAY): step cap, MIN_HIT_DIST and MAX_TRACE_DIST.
  int shadow_steps = 64;
  float min_hit_dist = 1e-3f;
  float max_trace_dist = 120.0f;
  bool hit_mask = false;  // MarchSettings::hit_mask: 1 inside a light, 2 inside the occluder
  // Where the outlines of shapes i < j cross: crossings[k] for k in [crossing_first[pairIndex(i,
  // j)], crossing_first[pairIndex(i, j) + 1]) (crossings.h).
  vec2 crossings[MAX_CROSSINGS] = {};
  int crossing_first[SHAPE_COUNT * SHAPE_COUNT + 1] = {};
  // For each pair i < j, at pairIndex(i, j): PAIR_*, and for PAIR_APART a line (x, y: a point,
  // z, w: the unit normal toward j) that separates them.
  int pair_mode[SHAPE_COUNT * SHAPE_COUNT] = {};
  glm::vec4 pair_line[SHAPE_COUNT * SHAPE_COUNT] = {};
};

// Whether shape j stands in the light of the others: the occluder, and every light that shines. A
// beam flickered fully out (gain 0, flicker_depth 1) is gone from the frame, so it casts no hard
// wall across the glows; a dimmed one still glows and still stands.
inline bool castsShadow(int j, const BeamsUniforms& u) {
  return j == OCCLUDER || u.gain[j] > 0.0f;
}

// Reads TIME, the parameters and the preset from ctx (ctx.params: this scene's parameters).
BeamsUniforms make_beams_uniforms(const FrameContext& ctx);

// The same values for the GLSL twin, named "u_beams.<field>" ("u_beams.shapes[2].a").
std::vector<ShaderUniform> beams_shader_uniforms(const BeamsUniforms& u);

// The seed's flicker(seed, speed) at TIME, as the continuous value it thresholds:
//   s = seed / speed + TIME
//   cos(sin(s / (0.1 pi)) + cos(1.5 s)) + sin(s / pi + cos(10 s))
// with every phase wrapped in double first, so that TIME = 1e6 flickers as TIME = 10 does.
float flicker_value(double seed, double speed, double scene_time);
// The seed's bool: flicker_value > 1.9 (a beam drops out while it holds).
bool flicker(double seed, double speed, double scene_time);
constexpr float FLICKER_THRESHOLD = 1.9f;

// Which estimator a preset uses: naive -> the seed's ray, draft and final -> penumbra,
// reference -> exact.
int estimator_for(const MarchSettings& m, Quality q);

}  // namespace sdfreel::light_beams
