// One pass of a user's shader: its uniforms (Shadertoy's, the camera's, the timeline's [params]),
// its channels and its draws, one per sub-pixel offset, summed by blending.
#include <glm/gtc/type_ptr.hpp>

#include "backends/gl/shadertoy_cube.h"
#include "backends/gl/shadertoy_runner.h"

namespace sdfreel {

void ShadertoyRunner::set_uniforms(const ShaderPass& pass, size_t index, const FrameContext& ctx,
                                   glm::ivec2 size) {
  auto f1 = [&](const char* name, float v) {
    if (GLint at = location(index, name); at >= 0) gl_.Uniform1fv(at, 1, &v);
  };
  auto f3 = [&](const char* name, const glm::vec3& v) {
    if (GLint at = location(index, name); at >= 0) gl_.Uniform3fv(at, 1, glm::value_ptr(v));
  };
  const float time = float(ctx.scene_time);
  f3("iResolution", {float(size.x), float(size.y), 1.0f});
  f1("iTime", time);
  f1("iTimeDelta", time_delta_);
  if (GLint at = location(index, "iFrame"); at >= 0) gl_.Uniform1iv(at, 1, &ctx.frame_index);
  f1("iFrameRate", float(ctx.fps));
  const float times[4] = {time, time, time, time};
  if (GLint at = location(index, "iChannelTime"); at >= 0) gl_.Uniform1fv(at, 4, times);
  float sizes[12] = {};
  for (size_t c = 0; c < 4; ++c) {
    const ChannelBinding& b = pass.channels[c];
    const glm::ivec2 read =
        b.kind == ChannelKind::Pass ? buffer_size(size_t(b.pass)) : texture_sizes_[index * 4 + c];
    sizes[3 * c] = float(read.x);
    sizes[3 * c + 1] = float(read.y);
    sizes[3 * c + 2] = b.kind == ChannelKind::None ? 0.0f : 1.0f;
  }
  if (GLint at = location(index, "iChannelResolution"); at >= 0) gl_.Uniform3fv(at, 4, sizes);
  const std::array<double, 4>& d = project_->date;
  const float date[4] = {float(d[0]), float(d[1]), float(d[2]), float(d[3] + ctx.scene_time)};
  if (GLint at = location(index, "iDate"); at >= 0) gl_.Uniform4fv(at, 1, date);
  f1("iSampleRate", float(project_->sample_rate));
  for (GLint c = 0; c < 4; ++c) {
    const char name[] = {'i', 'C', 'h', 'a', 'n', 'n', 'e', 'l', char('0' + c), '\0'};
    if (GLint at = location(index, name); at >= 0) gl_.Uniform1iv(at, 1, &c);
  }
  f3("iCameraPosition", glm::vec3(ctx.pose.position));
  f3("iCameraTarget", glm::vec3(ctx.pose.target));
  f3("iCameraUp", ctx.camera.up);
  f1("iCameraFov", float(ctx.pose.fov_deg));
  f1("iCameraFocal", 1.0f / ctx.camera.tan_half_fov);
  const glm::mat3 to_world(ctx.camera.right, ctx.camera.up, ctx.camera.forward);
  if (GLint at = location(index, "iCameraToWorld"); at >= 0)
    gl_.UniformMatrix3fv(at, 1, GL_FALSE, glm::value_ptr(to_world));
  // iMouse and the shader's own uniforms: the timeline's [params], animated.
  Program& program = programs_[index];
  const std::vector<ParamSpec>& specs = ctx.params.specs();  // the same every frame of a render
  if (!program.params_found) {
    for (const ParamSpec& spec : specs)
      program.param_locations.push_back(gl_.GetUniformLocation(program.id, spec.name.c_str()));
    program.params_found = true;
  }
  for (size_t i = 0; i < specs.size(); ++i) {
    const GLint at = program.param_locations[i];
    if (at < 0) continue;
    float v[4] = {};
    const std::vector<double>& raw = ctx.params.values()[i];
    for (size_t c = 0; c < raw.size() && c < 4; ++c) v[c] = float(raw[c]);
    switch (specs[i].components) {
      case 1:
        gl_.Uniform1fv(at, 1, v);
        break;
      case 2:
        gl_.Uniform2fv(at, 1, v);
        break;
      case 3:
        gl_.Uniform3fv(at, 1, v);
        break;
      default:
        gl_.Uniform4fv(at, 1, v);
        break;
    }
  }
}

void ShadertoyRunner::run_pass(const ShaderPass& pass, size_t index, const FrameContext& ctx,
                               GLuint target, GLenum face, const std::vector<glm::vec2>& offsets) {
  const bool cube_face = face != GL_TEXTURE_2D;
  const glm::ivec2 size = buffer_size(size_t(pass.kind));  // Image: the frame's, as a buffer's
  gl_.BindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  gl_.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, face, target, 0);
  const GLenum draw = GL_COLOR_ATTACHMENT0;
  gl_.DrawBuffers(1, &draw);
  gl_.Viewport(0, 0, size.x, size.y);
  const float zero[4] = {0, 0, 0, 0};
  gl_.ClearBufferfv(GL_COLOR, 0, zero);
  gl_.UseProgram(programs_[index].id);
  gl_.BindVertexArray(vao_);
  set_uniforms(pass, index, ctx, size);
  if (GLint at = location(index, "sdfreel_corners"); at >= 0 && cube_face)
    gl_.Uniform3fv(
        at, 5, glm::value_ptr(cube_face_corners(int(face - GL_TEXTURE_CUBE_MAP_POSITIVE_X))[0]));
  for (size_t c = 0; c < 4; ++c) {
    const ChannelBinding& b = pass.channels[c];
    GLuint tex = 0;
    GLenum kind = GL_TEXTURE_2D;
    if (b.kind == ChannelKind::Pass) {
      const Buffer& buf = buffers_[size_t(b.pass)];
      tex = buf.texture[buf.front];
      kind = buffer_target(size_t(b.pass));
    } else if (b.kind == ChannelKind::Texture || b.kind == ChannelKind::Cubemap) {
      tex = textures_[index * 4 + c];
      kind = texture_targets_[index * 4 + c];
    }
    gl_.ActiveTexture(GLenum(GL_TEXTURE0 + c));
    gl_.BindTexture(GL_TEXTURE_2D, kind == GL_TEXTURE_2D ? tex : 0);
    gl_.BindTexture(GL_TEXTURE_CUBE_MAP, kind == GL_TEXTURE_CUBE_MAP ? tex : 0);
    gl_.BindSampler(GLuint(c), samplers_[index * 4 + c]);
  }
  gl_.ActiveTexture(GL_TEXTURE0);
  if (offsets.size() > 1) {
    gl_.Enable(GL_BLEND);
    gl_.BlendEquation(GL_FUNC_ADD);
    gl_.BlendFunc(GL_ONE, GL_ONE);
  }
  const GLint at = location(index, "sdfreel_offset");
  for (const glm::vec2& o : offsets) {
    if (at >= 0) gl_.Uniform2fv(at, 1, glm::value_ptr(o));
    gl_.DrawArraysInstanced(GL_TRIANGLES, 0, 3, 1);
  }
  gl_.Disable(GL_BLEND);
  for (GLuint c = 0; c < 4; ++c) gl_.BindSampler(c, 0);
  gl_.check(std::string("running the ") + pass_name(pass.kind) + " pass");
}

}  // namespace sdfreel
