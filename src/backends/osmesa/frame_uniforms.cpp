#include "backends/osmesa/frame_uniforms.h"

#include <stdexcept>
#include <string>

namespace sdfreel {

namespace {

ShaderUniform scalar(const std::string& name, float v) {
  return {name, 1, {v}};
}
ShaderUniform vec3(const std::string& name, const glm::vec3& v) {
  return {name, 3, {v.x, v.y, v.z}};
}

}  // namespace

std::vector<ShaderUniform> frame_uniforms(const FrameContext& ctx) {
  const int n = int(ctx.sample_offsets.size());
  if (n < 1 || n > MAX_SHADER_SAMPLES)
    throw std::invalid_argument("the OSMesa backend takes 1.." +
                                std::to_string(MAX_SHADER_SAMPLES) + " samples per pixel, not " +
                                std::to_string(n));
  const CameraBasis& cam = ctx.camera;
  const MarchSettings& m = ctx.march;
  std::vector<ShaderUniform> u = {
      {"u_resolution", 2, {float(ctx.width), float(ctx.height)}},
      scalar("u_frame", float(ctx.frame_index)),
      scalar("u_time", float(ctx.scene_time)),
      vec3("u_camera_origin", cam.origin),
      vec3("u_camera_right", cam.right),
      vec3("u_camera_up", cam.up),
      vec3("u_camera_forward", cam.forward),
      scalar("u_tan_half_fov", cam.tan_half_fov),
      // Same expressions as CpuBackend::render, evaluated in float on the host.
      scalar("u_pixel_angle", footprint_angle(cam.tan_half_fov, ctx.height)),
      scalar("u_inv_samples", 1.0f / float(n)),
      scalar("u_sample_count", float(n)),
      scalar("u_march.max_steps", float(m.max_steps)),
      scalar("u_march.hit_eps", m.hit_eps),
      scalar("u_march.step_factor", m.step_factor),
      scalar("u_march.normal_eps", m.normal_eps),
      scalar("u_march.shadow_steps", float(m.shadow_steps)),
      scalar("u_march.reflect_steps", float(m.reflect_steps)),
      scalar("u_march.max_dist", m.max_dist),
  };
  ShaderUniform offsets{"u_sample_offsets", 2, {}};
  for (const glm::vec2& o : ctx.sample_offsets) {
    offsets.values.push_back(o.x);
    offsets.values.push_back(o.y);
  }
  u.push_back(std::move(offsets));
  // Every parameter, read through ParamValues as the C++ scenes read it.
  if (!ctx.params.values().empty())
    for (const ParamSpec& spec : ctx.params.specs()) {
      if (spec.components == 3)
        u.push_back(vec3("p_" + spec.name, ctx.params.vec3(spec.name)));
      else
        u.push_back(scalar("p_" + spec.name, float(ctx.params.scalar(spec.name))));
    }
  return u;
}

}  // namespace sdfreel
