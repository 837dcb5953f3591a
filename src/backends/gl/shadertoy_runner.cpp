#include "backends/gl/shadertoy_runner.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "backends/gl/gl_program.h"
#include "backends/gl/shadertoy_cube.h"
#include "backends/gl/shadertoy_source.h"
#include "shader/shadertoy_uniforms.h"

namespace sdfreel {

namespace {

GLuint float_texture(const GlApi& gl, int width, int height, const float* pixels) {
  GLuint t = 0;
  gl.GenTextures(1, &t);
  gl.BindTexture(GL_TEXTURE_2D, t);
  gl.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, width, height, 0, GL_RGBA, GL_FLOAT, pixels);
  gl.GenerateMipmap(GL_TEXTURE_2D);  // every level defined: any channel filter may read it
  return t;
}

GLuint make_sampler(const GlApi& gl, const ChannelBinding& b) {
  GLuint s = 0;
  gl.GenSamplers(1, &s);
  const GLint mag = b.filter == Filter::Nearest ? GL_NEAREST : GL_LINEAR;
  const GLint min = b.filter == Filter::Mipmap ? GL_LINEAR_MIPMAP_LINEAR : mag;
  const GLint wrap = b.wrap == Wrap::Repeat ? GL_REPEAT : GL_CLAMP_TO_EDGE;
  gl.SamplerParameteri(s, GL_TEXTURE_MAG_FILTER, mag);
  gl.SamplerParameteri(s, GL_TEXTURE_MIN_FILTER, min);
  gl.SamplerParameteri(s, GL_TEXTURE_WRAP_S, wrap);
  gl.SamplerParameteri(s, GL_TEXTURE_WRAP_T, wrap);
  return s;
}

}  // namespace

ShadertoyRunner::ShadertoyRunner(const GlApi& gl, const std::string& shader_dir,
                                 std::shared_ptr<const ShaderProject> project)
    : gl_(gl), project_(std::move(project)) {
  gl_.Enable(GL_TEXTURE_CUBE_MAP_SEAMLESS);  // filtering across cube edges, as WebGL 2 does
  std::string log;
  const GLuint vs = compile_fullscreen_vertex(gl_, shader_dir);
  for (const ShaderPass& pass : project_->passes) {
    const GLuint fs = compile_shader_text(gl_, GL_FRAGMENT_SHADER,
                                          shadertoy_fragment_source(*project_, pass), &log);
    if (!fs) {
      gl_.DeleteShader(vs);
      throw shadertoy_compile_error(*project_, pass, log);
    }
    Program p;
    p.id = gl_.CreateProgram();
    gl_.AttachShader(p.id, vs);
    gl_.AttachShader(p.id, fs);
    gl_.LinkProgram(p.id);
    gl_.DeleteShader(fs);
    GLint ok = GL_FALSE;
    gl_.GetProgramiv(p.id, GL_LINK_STATUS, &ok);
    if (!ok) {
      gl_.DeleteShader(vs);
      throw shadertoy_compile_error(*project_, pass,
                                    pass.kind == PassKind::CubeA
                                        ? "link error (check mainCubemap's signature)"
                                        : "link error (check mainImage's signature)");
    }
    for (const ShadertoyUniform& u : shadertoy_uniforms())
      p.locations.emplace_back(u.name, gl_.GetUniformLocation(p.id, u.name));
    for (const char* name : {"sdfreel_offset", "sdfreel_corners"})
      p.locations.emplace_back(name, gl_.GetUniformLocation(p.id, name));
    programs_.push_back(std::move(p));
    for (const ChannelBinding& b : pass.channels) {
      samplers_.push_back(make_sampler(gl_, b));
      GLuint tex = 0;
      GLenum target = GL_TEXTURE_2D;
      glm::ivec2 size(0);
      if ((b.kind == ChannelKind::Cubemap && !b.cube) ||
          (b.kind == ChannelKind::Texture && !b.image))
        throw std::logic_error("ShadertoyRunner: an image channel not read (load_channel_images)");
      if (b.kind == ChannelKind::Cubemap) {
        tex = cube_texture(gl_, b.cube->size, b.cube.get());
        target = GL_TEXTURE_CUBE_MAP;
        size = {b.cube->size, b.cube->size};
      } else if (b.kind == ChannelKind::Texture) {
        ImageRGBA image = *b.image;
        // Uploaded as read, the file's top row would be GL's row 0, at v = 0 (the bottom): the
        // picture upside down, as WebGL shows it without flipping. Shadertoy's vflip (its
        // default) flips it upright: the bottom row first.
        if (b.vflip) {
          for (int y = 0; y < image.height / 2; ++y)
            std::swap_ranges(image.at(0, y), image.at(0, y) + 4 * image.width,
                             image.at(0, image.height - 1 - y));
        }
        tex = float_texture(gl_, image.width, image.height, image.pixels.data());
        size = {image.width, image.height};
      }
      textures_.push_back(tex);
      texture_targets_.push_back(target);
      texture_sizes_.push_back(size);
    }
  }
  gl_.DeleteShader(vs);
  for (const ShaderPass& pass : project_->passes)
    for (const ChannelBinding& b : pass.channels)
      if (b.kind == ChannelKind::Pass && b.filter == Filter::Mipmap)
        mipmapped_[size_t(b.pass)] = true;
  gl_.GenVertexArrays(1, &vao_);
  gl_.GenFramebuffers(1, &framebuffer_);
  gl_.check("compiling the shader's passes");
}

ShadertoyRunner::~ShadertoyRunner() {
  for (const Program& p : programs_) gl_.DeleteProgram(p.id);
  for (GLuint t : textures_)
    if (t) gl_.DeleteTextures(1, &t);
  for (GLuint s : samplers_) gl_.DeleteSamplers(1, &s);
  for (Buffer& b : buffers_)
    if (b.texture[0]) gl_.DeleteTextures(2, b.texture);
  if (image_texture_) gl_.DeleteTextures(1, &image_texture_);
  gl_.DeleteFramebuffers(1, &framebuffer_);
  gl_.DeleteVertexArrays(1, &vao_);
}

void ShadertoyRunner::resize(int width, int height) {
  if (width == width_ && height == height_) return;
  for (Buffer& b : buffers_)
    if (b.texture[0]) gl_.DeleteTextures(2, b.texture), b = Buffer{};
  if (image_texture_) gl_.DeleteTextures(1, &image_texture_);
  for (const ShaderPass& pass : project_->passes)
    if (pass.kind != PassKind::Image)
      for (GLuint& t : buffers_[size_t(pass.kind)].texture)
        t = pass.kind == PassKind::CubeA ? cube_texture(gl_, project_->cube_size, nullptr)
                                         : float_texture(gl_, width, height, nullptr);
  image_texture_ = float_texture(gl_, width, height, nullptr);
  width_ = width;
  height_ = height;
  buffers_at_ = -1;
}

void ShadertoyRunner::clear_buffers() {
  const float zero[4] = {0, 0, 0, 0};
  gl_.BindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  for (size_t k = 0; k < buffers_.size(); ++k)
    for (GLuint t : buffers_[k].texture)
      if (t) {
        for (int f = 0; f < buffer_faces(k); ++f) {
          gl_.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, face_target(k, f), t, 0);
          gl_.ClearBufferfv(GL_COLOR, 0, zero);
        }
        if (mipmapped_[k])
          gl_.BindTexture(buffer_target(k), t), gl_.GenerateMipmap(buffer_target(k));
      }
  buffers_at_ = -1;
}

GLenum ShadertoyRunner::buffer_target(size_t kind) const {
  return kind == size_t(PassKind::CubeA) ? GL_TEXTURE_CUBE_MAP : GL_TEXTURE_2D;
}

glm::ivec2 ShadertoyRunner::buffer_size(size_t kind) const {
  return kind == size_t(PassKind::CubeA) ? glm::ivec2(project_->cube_size)
                                         : glm::ivec2(width_, height_);
}

GLenum ShadertoyRunner::face_target(size_t kind, int face) const {
  return kind == size_t(PassKind::CubeA) ? GLenum(GL_TEXTURE_CUBE_MAP_POSITIVE_X + face)
                                         : GLenum(GL_TEXTURE_2D);
}

FrameContext ShadertoyRunner::context(int frame) const {
  if (!source_) throw std::logic_error("ShadertoyRunner: no frame source for a replay");
  return source_(frame);
}

// TIME's step to this frame from the one before (frame 0: to the next one, so it is never 0).
float ShadertoyRunner::time_delta(const FrameContext& ctx) const {
  if (!source_) return float(1.0 / ctx.fps);
  const int other = ctx.frame_index > 0 ? ctx.frame_index - 1 : ctx.frame_index + 1;
  return float(std::abs(ctx.scene_time - source_(other).scene_time));
}

GLint ShadertoyRunner::location(size_t index, const char* name) const {
  for (const auto& [n, at] : programs_[index].locations)
    if (n == name) return at;
  return -1;
}

void ShadertoyRunner::run_buffers(const FrameContext& ctx) {
  time_delta_ = time_delta(ctx);
  for (size_t i = 0; i < project_->passes.size(); ++i) {
    const ShaderPass& pass = project_->passes[i];
    if (pass.kind == PassKind::Image) continue;
    const size_t k = size_t(pass.kind);
    Buffer& b = buffers_[k];
    for (int f = 0; f < buffer_faces(k); ++f)
      run_pass(pass, i, ctx, b.texture[1 - b.front], face_target(k, f), {glm::vec2(0.5f)});
    b.front = 1 - b.front;
    if (mipmapped_[k]) {  // only where a reader samples its mip levels
      gl_.BindTexture(buffer_target(k), b.texture[b.front]);
      gl_.GenerateMipmap(buffer_target(k));
    }
  }
}

// Frame k needs the buffers of frames 0..k-1: what is missing comes from the latest checkpoint
// that saves work, then a replay.
void ShadertoyRunner::catch_up(int k) {
  if (buffers_at_ >= k || buffers_at_ < 0) clear_buffers();
  if (buffers_at_ + 1 == k) return;
  if (checkpoints_)
    if (auto state = checkpoints_->latest(buffers_at_ + 2, k, width_, height_);
        state && restore(*state)) {
      std::fprintf(stderr, "restarting the shader's buffers from the checkpoint before frame %d\n",
                   state->next_frame);
    }
  if (buffers_at_ + 1 < k)  // a start, a shard or a resume: say why the first frame is slow
    std::fprintf(stderr,
                 "replaying the shader's buffers of frames %d-%d for frame %d (its frames "
                 "depend on the ones before)\n",
                 buffers_at_ + 1, k - 1, k);
  for (int i = buffers_at_ + 1; i < k; ++i) {
    run_buffers(context(i));
    buffers_at_ = i;
    keep_checkpoint();
  }
}

bool ShadertoyRunner::restore(const BufferState& state) {
  for (size_t k = 0; k < buffers_.size(); ++k) {
    const glm::ivec2 size = buffer_size(k);
    const size_t texels = size_t(size.x) * size_t(size.y) * 4 * size_t(buffer_faces(k));
    if (state.buffers[k].size() != (buffers_[k].texture[0] ? texels : 0)) return false;
  }
  for (size_t k = 0; k < buffers_.size(); ++k) {
    Buffer& b = buffers_[k];
    if (!b.texture[0]) continue;
    const glm::ivec2 size = buffer_size(k);
    gl_.BindTexture(buffer_target(k), b.texture[b.front]);
    for (int f = 0; f < buffer_faces(k); ++f)
      gl_.TexImage2D(face_target(k, f), 0, GL_RGBA32F, size.x, size.y, 0, GL_RGBA, GL_FLOAT,
                     state.buffers[k].data() + size_t(f) * size_t(size.x) * size_t(size.y) * 4);
    if (mipmapped_[k]) gl_.GenerateMipmap(buffer_target(k));  // as run_buffers leaves it
  }
  gl_.check("restoring the shader's buffers from a checkpoint");
  buffers_at_ = state.next_frame - 1;
  return true;
}

void ShadertoyRunner::keep_checkpoint() {
  const int next = buffers_at_ + 1;
  if (!checkpoints_ || next % checkpoints_->every() != 0 || checkpoints_->has(next)) return;
  BufferState state{next, width_, height_, project_->cube_size, {}};
  gl_.BindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  gl_.ReadBuffer(GL_COLOR_ATTACHMENT0);
  gl_.PixelStorei(GL_PACK_ALIGNMENT, 4);
  for (size_t k = 0; k < buffers_.size(); ++k) {
    const Buffer& b = buffers_[k];
    if (!b.texture[0]) continue;
    const glm::ivec2 size = buffer_size(k);
    const size_t face_texels = size_t(size.x) * size_t(size.y) * 4;
    state.buffers[k].resize(face_texels * size_t(buffer_faces(k)));
    for (int f = 0; f < buffer_faces(k); ++f) {
      gl_.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, face_target(k, f),
                               b.texture[b.front], 0);
      gl_.ReadPixels(0, 0, size.x, size.y, GL_RGBA, GL_FLOAT,
                     state.buffers[k].data() + size_t(f) * face_texels);
    }
  }
  gl_.check("reading the shader's buffers for a checkpoint");
  checkpoints_->save(state);
}

ImageRGBA ShadertoyRunner::render(const FrameContext& ctx) {
  resize(ctx.width, ctx.height);
  const int k = ctx.frame_index;
  if (project_->has_feedback()) catch_up(k);
  // Without feedback every buffer is written before any pass reads it: nothing to catch up.
  run_buffers(ctx);  // also sets this frame's iTimeDelta, which the Image pass reads
  buffers_at_ = k;
  keep_checkpoint();

  std::vector<glm::vec2> offsets;  // GL's fragCoord counts rows from the bottom
  for (const glm::vec2& o : ctx.sample_offsets) offsets.push_back({o.x, 1.0f - o.y});
  const ShaderPass& image = project_->passes.back();
  run_pass(image, project_->passes.size() - 1, ctx, image_texture_, GL_TEXTURE_2D, offsets);

  ImageRGBA out(ctx.width, ctx.height);
  gl_.BindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  gl_.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, image_texture_, 0);
  gl_.ReadBuffer(GL_COLOR_ATTACHMENT0);
  gl_.PixelStorei(GL_PACK_ALIGNMENT, 4);
  std::vector<float> rows(out.pixels.size());
  gl_.ReadPixels(0, 0, ctx.width, ctx.height, GL_RGBA, GL_FLOAT, rows.data());
  gl_.check("reading the shader's image");
  // Samples summed in the target in draw order; the mean here, alpha 1 as Shadertoy shows it.
  const float inv = 1.0f / float(offsets.size());
  for (int y = 0; y < ctx.height; ++y) {
    const float* src = &rows[size_t(ctx.height - 1 - y) * size_t(ctx.width) * 4];
    float* dst = out.at(0, y);
    for (int x = 0; x < ctx.width; ++x) {
      for (int c = 0; c < 3; ++c) dst[4 * x + c] = src[4 * x + c] * inv;
      dst[4 * x + 3] = 1.0f;
    }
  }
  return out;
}

}  // namespace sdfreel
