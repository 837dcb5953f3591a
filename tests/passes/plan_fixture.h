#pragma once
// Small frame plans for the pass tests of both backends: a frame context without a scene, an
// occlusion pattern both backends compute exactly (integers), and the closed form of the
// crepuscular-rays sum over uniform occlusion.
#include <cmath>

#include "render/frame_context.h"
#include "render/frame_plan.h"

namespace sdfreel::test {

inline FrameContext plan_context(int width, int height, int samples = 1) {
  FrameContext ctx;
  ctx.width = width;
  ctx.height = height;
  ctx.samples = samples;
  finish_frame_context(ctx);
  return ctx;
}

// 1 where the light is seen: a checker of 5x3-pixel cells with a lit disc-free hole, as integers.
inline float occlusion_pattern(int x, int y) {
  return float(((x / 5) + (y / 3)) % 2);
}

// An image pass writing `value` (uniform occlusion) or the pattern into `target`; GL shader
// tests/gl/shaders/occlusion_fill.glsl.
inline ImagePass occlusion_fill(const std::string& target, bool pattern, float value) {
  ImagePass p;
  p.name = "occlusion fill";
  p.output = target;
  p.shader = "occlusion_fill.glsl";
  p.uniforms = {{"u_pattern", 1, {pattern ? 1.0f : 0.0f}}, {"u_value", 1, {value}}};
  p.pixel = [pattern, value](const ImageInputs&, int x, int y) {
    const float v = pattern ? occlusion_pattern(x, y) : value;
    return glm::vec4(v, v, v, 1.0f);
  };
  return p;
}

// exposure * c * weight * (1 - decay^N) / (1 - decay), N * weight when decay = 1: the N taps
// weight * decay^k, k = 0 .. N - 1.
inline double crepuscular_closed_form(double c, int n, double weight, double decay,
                                      double exposure) {
  const double sum =
      decay == 1.0 ? n * weight : weight * (1.0 - std::pow(decay, n)) / (1.0 - decay);
  return exposure * c * sum;
}

}  // namespace sdfreel::test
