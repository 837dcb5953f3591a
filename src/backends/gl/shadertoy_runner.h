#pragma once
// Runs a user's Shadertoy shader (docs/shaders.md) on the current GL context: every buffer pass
// once per frame at the frame's size into float ping-pong textures (a pass reads the latest output
// of each buffer: this frame's when it ran before, the previous frame's otherwise, itself
// included), then the Image pass once per sub-pixel sample offset, summed in a float target in
// fixed order. A shader with feedback replays its buffers (buffers only) whenever a frame does not
// follow the one before it, from the latest checkpoint of their state if the render keeps them,
// else from frame 0, so every frame has the same bits however it is reached.
#include <array>
#include <functional>
#include <memory>
#include <vector>

#include "backends/gl/gl_api.h"
#include "render/buffer_checkpoints.h"
#include "render/frame_context.h"
#include "render/image.h"
#include "shader/shader_project.h"

namespace sdfreel {

class ShadertoyRunner {
 public:
  // Compiles every pass (InputError naming the user's file and line) and uploads the textures.
  // `shader_dir`: sdfreel's own GLSL (the full-screen vertex shader).
  ShadertoyRunner(const GlApi& gl, const std::string& shader_dir,
                  std::shared_ptr<const ShaderProject> project);
  ~ShadertoyRunner();
  ShadertoyRunner(const ShadertoyRunner&) = delete;
  ShadertoyRunner& operator=(const ShadertoyRunner&) = delete;

  // The context of any frame, for replays and iTimeDelta.
  void set_frame_source(std::function<FrameContext(int)> source) { source_ = std::move(source); }
  // Where the buffers' state is kept every N frames and restored from (nullptr: nowhere; given
  // only to a shader with feedback, pipeline/shader_checkpoints.h).
  void set_checkpoints(std::shared_ptr<BufferCheckpoints> c) { checkpoints_ = std::move(c); }
  // The display-referred (or linear, [shader] output) RGBA image of ctx's frame, row 0 at the top.
  ImageRGBA render(const FrameContext& ctx);

 private:
  struct Program {
    GLuint id = 0;
    std::vector<std::pair<std::string, GLint>> locations;  // sdfreel's uniforms
    std::vector<GLint> param_locations;  // the timeline's [params], looked up at the first frame
    bool params_found = false;
  };
  struct Buffer {  // a buffer pass's two textures: front is its latest output
    GLuint texture[2] = {0, 0};
    int front = 0;
  };
  void resize(int width, int height);
  void clear_buffers();
  void run_buffers(const FrameContext& ctx);
  void catch_up(int frame);  // buffers of frames before `frame`: from a checkpoint or replayed
  bool restore(const BufferState& state);  // false: its buffers are not this shader's
  void keep_checkpoint();  // after the buffers of frame buffers_at_, when one is due
  // Draws into `target`'s level 0: a 2D texture (face GL_TEXTURE_2D) or a face of Cube A.
  void run_pass(const ShaderPass& pass, size_t index, const FrameContext& ctx, GLuint target,
                GLenum face, const std::vector<glm::vec2>& offsets);
  void set_uniforms(const ShaderPass& pass, size_t index, const FrameContext& ctx, glm::ivec2 size);
  GLenum buffer_target(size_t kind) const;    // GL_TEXTURE_CUBE_MAP for Cube A
  glm::ivec2 buffer_size(size_t kind) const;  // the frame's (Image's too), or Cube A's faces
  int buffer_faces(size_t kind) const { return kind == size_t(PassKind::CubeA) ? 6 : 1; }
  GLenum face_target(size_t kind, int face) const;
  GLint location(size_t index, const char* name) const;
  FrameContext context(int frame) const;
  float time_delta(const FrameContext& ctx) const;

  const GlApi& gl_;
  std::shared_ptr<const ShaderProject> project_;
  std::function<FrameContext(int)> source_;
  std::shared_ptr<BufferCheckpoints> checkpoints_;
  std::vector<Program> programs_;        // one per pass, in project order
  std::array<Buffer, 5> buffers_{};      // by PassKind (BufferA..CubeA)
  std::array<bool, 5> mipmapped_{};      // by PassKind: some channel reads it with mipmap filtering
  std::vector<GLuint> textures_;         // by pass index * 4 + channel: image files, 0 otherwise
  std::vector<GLenum> texture_targets_;  // GL_TEXTURE_2D or GL_TEXTURE_CUBE_MAP, the same way
  std::vector<glm::ivec2> texture_sizes_;
  std::vector<GLuint> samplers_;  // by pass index * 4 + channel
  GLuint framebuffer_ = 0, image_texture_ = 0, vao_ = 0;
  int width_ = 0, height_ = 0;
  int buffers_at_ = -1;      // the last frame whose buffer passes ran, -1 none
  float time_delta_ = 0.0f;  // iTimeDelta of the frame being rendered
};

}  // namespace sdfreel
