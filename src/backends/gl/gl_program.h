#pragma once
// A linked GLSL program and what it expects: its active uniforms by name (arrays under their base
// name), so the driver can check and convert the values each pass supplies.
#include <map>
#include <string>

#include "backends/gl/gl_api.h"
#include "backends/gl/shader_source.h"

namespace sdfreel {

struct GlUniformInfo {
  GLint location = -1;
  GLenum type = 0;  // GL_FLOAT_VEC3, GL_INT, GL_SAMPLER_2D, ...
  GLint size = 1;   // array length
};

struct GlProgramFiles {
  std::string vertex;  // path under the shader folder
  std::string fragment;
  std::string defines;  // extra preamble lines ("#define X 1\n"), after #version
};

struct GlProgram {
  GLuint id = 0;
  std::string name;  // the fragment file, for messages
  std::map<std::string, GlUniformInfo> uniforms;
};

// Loads, compiles and links; ShaderError with FILE:LINE messages on failure. Needs a current
// context.
GlProgram build_program(const GlApi& gl, const std::string& shader_dir, const GlProgramFiles& f);

// Compiles one stage from its whole text (#version included); 0, with the compiler's log in *log,
// when it does not compile. Needs a current context.
GLuint compile_shader_text(const GlApi& gl, GLenum stage, const std::string& text,
                           std::string* log);
// The full-screen triangle's vertex shader (common/fullscreen.vert), compiled; ShaderError when
// it does not compile.
GLuint compile_fullscreen_vertex(const GlApi& gl, const std::string& shader_dir);

// Components per element of a uniform type (vec3 -> 3); 0 for samplers and unsupported types.
int uniform_components(GLenum type);
bool is_sampler(GLenum type);

}  // namespace sdfreel
