#pragma once
// The march settings a marching scene's uniform struct carries (max_steps, shadow_steps,
// reflect_steps, hit_eps, step_factor, normal_eps, max_dist, naive, hit_mask, surface), copied from
// the frame and named for GLSL the same way by every such scene.
#include "render/quality.h"
#include "scenes/common/uniform_list.h"

namespace sdfreel {

template <class Uniforms>
void copy_march_settings(const MarchSettings& m, Uniforms& u) {
  u.max_steps = m.max_steps;
  u.shadow_steps = m.shadow_steps;
  u.reflect_steps = m.reflect_steps;
  u.hit_eps = m.hit_eps;
  u.step_factor = m.step_factor;
  u.normal_eps = m.normal_eps;
  u.max_dist = m.max_dist;
  u.naive = m.naive;
  u.hit_mask = m.hit_mask;
  u.surface = m.surface;
}

template <class Uniforms>
UniformList& add_march_uniforms(UniformList& list, const Uniforms& u) {
  return list.f("max_steps", float(u.max_steps))
      .f("shadow_steps", float(u.shadow_steps))
      .f("reflect_steps", float(u.reflect_steps))
      .f("hit_eps", u.hit_eps)
      .f("step_factor", u.step_factor)
      .f("normal_eps", u.normal_eps)
      .f("max_dist", u.max_dist)
      .flag("naive", u.naive)
      .flag("hit_mask", u.hit_mask)
      .f("surface", float(u.surface));
}

}  // namespace sdfreel
