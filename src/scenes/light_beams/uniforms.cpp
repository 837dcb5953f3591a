#include "scenes/light_beams/uniforms.h"

#include <string>

#include "scenes/light_beams/crossings.h"

namespace sdfreel::light_beams {
namespace {

constexpr double TWO_PI_D = 6.283185307179586;

// The fixed lights, in the world units of the default view (x in [-16/9, 16/9], y in [-1, 1]).
struct LightSpec {
  int type;
  vec2 a, b;
  float r;
  glm::vec3 color;
};
const LightSpec LIGHTS[LIGHT_COUNT] = {
    {SHAPE_CIRCLE, {-0.95f, 0.35f}, {0.0f, 0.0f}, 0.11f, {1.0f, 0.42f, 0.12f}},       // amber
    {SHAPE_CIRCLE, {1.05f, -0.25f}, {0.0f, 0.0f}, 0.08f, {0.25f, 0.55f, 1.0f}},       // blue
    {SHAPE_SEGMENT, {-0.55f, -0.55f}, {0.05f, -0.35f}, 0.022f, {1.0f, 0.2f, 0.55f}},  // pink
    {SHAPE_SEGMENT, {0.35f, 0.62f}, {0.95f, 0.42f}, 0.018f, {0.2f, 1.0f, 0.7f}},      // teal
};

// The vertical beams: resting x, sway rate and phase, and the seed/speed pair of each beam's
// flicker (chosen so that the beams drop out at different moments).
struct BeamSpec {
  float x, rate, phase;
  double flicker_seed, flicker_speed;
};
const BeamSpec BEAMS[BEAM_COUNT] = {
    {-1.25f, 0.7f, 0.0f, 1.7, 1.0},
    {-0.45f, 1.1f, 2.1f, 4.3, 0.8},
    {0.4f, 0.9f, 4.0f, 7.1, 1.3},
    {1.3f, 1.3f, 1.2f, 9.9, 0.6},
};
constexpr float BEAM_STROKE = 0.006f;
const glm::vec3 BEAM_COLOR(0.75f, 0.85f, 1.0f);

}  // namespace

int estimator_for(const MarchSettings& m, Quality q) {
  if (m.naive) return ESTIMATOR_SEED_RAY;
  return q == Quality::Reference ? ESTIMATOR_EXACT : ESTIMATOR_PENUMBRA;
}

BeamsUniforms make_beams_uniforms(const FrameContext& ctx) {
  const ParamValues& pv = ctx.params;
  BeamsUniforms u;
  const float light_gain = float(pv.scalar("light_intensity"));
  for (int i = 0; i < LIGHT_COUNT; ++i) {
    const LightSpec& l = LIGHTS[i];
    u.shapes[i] = Shape{l.type, l.a, l.b, l.r};
    u.color[i] = l.color;
    u.gain[i] = light_gain;
    u.fades[i] = 0.0f;
  }
  const double sway_rate = pv.scalar("beam_speed");
  const float sway = float(pv.scalar("beam_sway"));
  const float beam_gain = light_gain * float(pv.scalar("beam_intensity"));
  const float dropped = 1.0f - float(pv.scalar("flicker_depth"));
  const float half_length = float(pv.scalar("beam_half_length"));
  for (int k = 0; k < BEAM_COUNT; ++k) {
    const BeamSpec& b = BEAMS[k];
    const float phase = dm::wrap_phase(ctx.scene_time * sway_rate * b.rate + b.phase, TWO_PI_D);
    const float x = b.x + sway * dm::sin(phase);
    const int i = FIRST_BEAM + k;
    u.shapes[i] = Shape{SHAPE_SEGMENT, {x, -half_length}, {x, half_length}, BEAM_STROKE};
    u.color[i] = BEAM_COLOR;
    const bool off = flicker(b.flicker_seed, b.flicker_speed, ctx.scene_time);
    u.gain[i] = off ? beam_gain * dropped : beam_gain;
    u.fades[i] = 1.0f;
  }
  const vec2 occ(float(pv.scalar("occluder_x")), float(pv.scalar("occluder_y")));
  u.shapes[OCCLUDER] = Shape{SHAPE_CIRCLE, occ, occ, float(pv.scalar("occluder_radius"))};
  u.color[OCCLUDER] = glm::vec3(0.0f);
  u.gain[OCCLUDER] = 0.0f;
  u.fades[OCCLUDER] = 0.0f;
  u.glow_constant = float(pv.scalar("glow_constant"));
  u.glow_linear = float(pv.scalar("glow_linear"));
  u.glow_quadratic = float(pv.scalar("glow_quadratic"));
  u.background = pv.vec3("background");
  const MarchSettings& m = ctx.march;
  u.estimator = estimator_for(m, ctx.quality);
  u.shadow_steps = m.shadow_steps;
  u.min_hit_dist = m.hit_eps;
  u.max_trace_dist = m.max_dist;
  u.hit_mask = m.hit_mask;
  findCrossings(u);
  return u;
}

std::vector<ShaderUniform> beams_shader_uniforms(const BeamsUniforms& u) {
  const auto f = [](const std::string& name, float v) {
    return ShaderUniform{"u_beams." + name, 1, {v}};
  };
  const auto v2 = [](const std::string& name, const vec2& v) {
    return ShaderUniform{"u_beams." + name, 2, {v.x, v.y}};
  };
  const auto v3 = [](const std::string& name, const glm::vec3& v) {
    return ShaderUniform{"u_beams." + name, 3, {v.x, v.y, v.z}};
  };
  std::vector<ShaderUniform> out = {
      f("glow_constant", u.glow_constant),     f("glow_linear", u.glow_linear),
      f("glow_quadratic", u.glow_quadratic),   v3("background", u.background),
      f("estimator", float(u.estimator)),      f("shadow_steps", float(u.shadow_steps)),
      f("min_hit_dist", u.min_hit_dist),       f("max_trace_dist", u.max_trace_dist),
      f("hit_mask", u.hit_mask ? 1.0f : 0.0f),
  };
  // Arrays of structs are set element by element, arrays of plain types as a whole.
  ShaderUniform color{"u_beams.color", 3, {}}, gain{"u_beams.gain", 1, {}},
      fades{"u_beams.fades", 1, {}};
  for (int i = 0; i < SHAPE_COUNT; ++i) {
    const std::string s = "shapes[" + std::to_string(i) + "].";
    const Shape& sh = u.shapes[i];
    out.push_back(f(s + "type", float(sh.type)));
    out.push_back(v2(s + "a", sh.a));
    out.push_back(v2(s + "b", sh.b));
    out.push_back(f(s + "r", sh.r));
    color.values.insert(color.values.end(), {u.color[i].x, u.color[i].y, u.color[i].z});
    gain.values.push_back(u.gain[i]);
    fades.values.push_back(u.fades[i]);
  }
  out.push_back(color);
  out.push_back(gain);
  out.push_back(fades);
  ShaderUniform crossings{"u_beams.crossings", 2, {}}, first{"u_beams.crossing_first", 1, {}};
  for (const vec2& c : u.crossings) crossings.values.insert(crossings.values.end(), {c.x, c.y});
  for (const int k : u.crossing_first) first.values.push_back(float(k));
  out.push_back(crossings);
  out.push_back(first);
  ShaderUniform mode{"u_beams.pair_mode", 1, {}}, line{"u_beams.pair_line", 4, {}};
  for (const int m : u.pair_mode) mode.values.push_back(float(m));
  for (const glm::vec4& l : u.pair_line)
    line.values.insert(line.values.end(), {l.x, l.y, l.z, l.w});
  out.push_back(mode);
  out.push_back(line);
  return out;
}

}  // namespace sdfreel::light_beams
