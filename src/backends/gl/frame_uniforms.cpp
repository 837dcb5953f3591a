#include "backends/gl/frame_uniforms.h"

#include <stdexcept>
#include <string>
#include <utility>

#include "scenes/common/uniform_list.h"

namespace sdfreel {

std::vector<ShaderUniform> frame_uniforms(const FrameContext& ctx) {
  const int n = int(ctx.sample_offsets.size());
  if (n < 1 || n > MAX_SHADER_SAMPLES)
    throw std::invalid_argument("the OSMesa backend takes 1.." +
                                std::to_string(MAX_SHADER_SAMPLES) + " samples per pixel, not " +
                                std::to_string(n));
  const CameraBasis& cam = ctx.camera;
  const MarchSettings& m = ctx.march;
  std::vector<float> offsets;
  for (const glm::vec2& o : ctx.sample_offsets) {
    offsets.push_back(o.x);
    offsets.push_back(o.y);
  }
  UniformList u;
  u.v2("u_resolution", glm::vec2(float(ctx.width), float(ctx.height)))
      .f("u_frame", float(ctx.frame_index))
      .f("u_time", float(ctx.scene_time))
      .v3("u_camera_origin", cam.origin)
      .v3("u_camera_right", cam.right)
      .v3("u_camera_up", cam.up)
      .v3("u_camera_forward", cam.forward)
      .f("u_tan_half_fov", cam.tan_half_fov)
      // Same expressions as CpuBackend::render, evaluated in float on the host.
      .f("u_pixel_angle", footprint_angle(cam.tan_half_fov, ctx.height))
      .f("u_inv_samples", 1.0f / float(n))
      .f("u_sample_count", float(n))
      .f("u_march.max_steps", float(m.max_steps))
      .f("u_march.hit_eps", m.hit_eps)
      .f("u_march.step_factor", m.step_factor)
      .f("u_march.normal_eps", m.normal_eps)
      .f("u_march.shadow_steps", float(m.shadow_steps))
      .f("u_march.reflect_steps", float(m.reflect_steps))
      .f("u_march.max_dist", m.max_dist)
      .add("u_sample_offsets", 2, std::move(offsets));
  // Every parameter, read through ParamValues as the C++ scenes read it.
  if (!ctx.params.values().empty())
    for (const ParamSpec& spec : ctx.params.specs()) {
      if (spec.components == 3)
        u.v3("p_" + spec.name, ctx.params.vec3(spec.name));
      else
        u.f("p_" + spec.name, float(ctx.params.scalar(spec.name)));
    }
  return u.uniforms();
}

}  // namespace sdfreel
