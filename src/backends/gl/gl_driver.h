#pragma once
// The driver half of the GL backend: compiles programs, owns meshes, textures and off-screen
// render targets, and runs passes (gl_pass.h) on whatever context the platform made current. It
// knows nothing of OSMesa, scenes or frames.
#include <deque>
#include <map>
#include <string>
#include <vector>

#include "backends/gl/gl_pass.h"
#include "backends/gl/gl_platform.h"
#include "backends/gl/gl_program.h"
#include "render/image.h"

namespace sdfreel {

// An off-screen target whose colour attachments later passes can sample.
struct GlRenderTarget {
  GlTargetRef ref;
  std::vector<GLuint> color_textures;
  GLuint depth_buffer = 0;
};

class GlDriver {
 public:
  // The platform's context must be current for every call, including the destructor.
  GlDriver(GlPlatform& platform, std::string shader_dir);
  ~GlDriver();
  GlDriver(const GlDriver&) = delete;
  GlDriver& operator=(const GlDriver&) = delete;

  const std::string& shader_dir() const { return shader_dir_; }
  const GlApi& gl() const { return gl_; }

  // Throws ShaderError naming FILE:LINE on compile errors.
  GlProgramId compile(const GlProgramFiles& files);
  const GlProgram& program(GlProgramId id) const { return programs_.at(size_t(id)); }
  GlMeshId create_mesh(const GlMesh& mesh);
  // Per-instance attributes of `mesh` for the next draws: 20 floats an instance, the model
  // matrix column-major (attributes 3..6) and a free vec4 (attribute 7).
  void set_instances(GlMeshId mesh, const std::vector<float>& per_instance);
  // Creates the float texture named t.name, or refills it; returns its GL name. Nearest
  // filtering, clamped: shaders read texels with texelFetch and filter in code like the C++ does.
  GLuint upload_texture(const ShaderTexture& t);
  const GlRenderTarget& create_render_target(int width, int height, int colors, bool depth);

  void run(const GlPass& pass);
  // One colour attachment as a linear image, row 0 at the top (GL's row 0 is the bottom).
  ImageRGBA read_rgba(const GlTargetRef& target, int attachment = 0) const;

 private:
  struct MeshBuffers {
    GLuint vao = 0, buffers[5] = {0, 0, 0, 0, 0};  // position, normal, uv, index, instance
    GLsizei count = 0;
    bool indexed = false;
  };
  void set_uniforms(const GlPass& pass, const GlProgram& prog);
  void draw(const GlPass& pass);

  const GlApi& gl_;
  std::string shader_dir_;
  GLuint empty_vao_ = 0;  // core profile draws need a bound VAO even without attributes
  std::vector<GlProgram> programs_;
  std::vector<MeshBuffers> meshes_;
  std::map<std::string, GLuint> textures_;
  std::deque<GlRenderTarget> targets_;  // deque: references stay valid
};

}  // namespace sdfreel
