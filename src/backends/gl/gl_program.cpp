#include "backends/gl/gl_program.h"

#include <vector>

namespace sdfreel {

namespace {

constexpr const char* GLSL_VERSION = "#version 450 core\n";

std::string shader_log(const GlApi& gl, GLuint shader) {
  GLint length = 0;
  gl.GetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
  std::vector<char> log(size_t(length > 0 ? length : 1), '\0');
  gl.GetShaderInfoLog(shader, GLsizei(log.size()), nullptr, log.data());
  return log.data();
}

std::string program_log(const GlApi& gl, GLuint program) {
  GLint length = 0;
  gl.GetProgramiv(program, GL_INFO_LOG_LENGTH, &length);
  std::vector<char> log(size_t(length > 0 ? length : 1), '\0');
  gl.GetProgramInfoLog(program, GLsizei(log.size()), nullptr, log.data());
  return log.data();
}

GLuint compile_stage(const GlApi& gl, GLenum stage, const std::string& dir, const std::string& file,
                     const std::string& defines) {
  const ShaderSource src = load_shader_source(dir, file, GLSL_VERSION + defines);
  std::string log;
  const GLuint shader = compile_shader_text(gl, stage, src.text, &log);
  if (!shader) throw ShaderError("cannot compile " + file + ":\n" + map_shader_log(log, src, dir));
  return shader;
}

// "u_offsets[0]" -> "u_offsets": arrays of plain types are set from their first element. Arrays
// of structs are listed member by member ("u.boxes[1].dir") and keep their full names.
std::string base_name(const std::string& name) {
  const std::string first = "[0]";
  if (name.size() > first.size() &&
      name.compare(name.size() - first.size(), first.size(), first) == 0)
    return name.substr(0, name.size() - first.size());
  return name;
}

void reflect_uniforms(const GlApi& gl, GlProgram& p) {
  GLint count = 0, max_length = 0;
  gl.GetProgramiv(p.id, GL_ACTIVE_UNIFORMS, &count);
  gl.GetProgramiv(p.id, GL_ACTIVE_UNIFORM_MAX_LENGTH, &max_length);
  std::vector<char> name(size_t(max_length > 0 ? max_length : 1) + 1, '\0');
  for (GLint i = 0; i < count; ++i) {
    GlUniformInfo info;
    GLsizei length = 0;
    gl.GetActiveUniform(p.id, GLuint(i), GLsizei(name.size()), &length, &info.size, &info.type,
                        name.data());
    const std::string full(name.data(), size_t(length));
    info.location = gl.GetUniformLocation(p.id, full.c_str());
    if (info.location < 0) continue;  // block members: not set through locations
    p.uniforms[base_name(full)] = info;
  }
}

}  // namespace

GLuint compile_shader_text(const GlApi& gl, GLenum stage, const std::string& text,
                           std::string* log) {
  const GLuint shader = gl.CreateShader(stage);
  const char* p = text.c_str();
  gl.ShaderSource(shader, 1, &p, nullptr);
  gl.CompileShader(shader);
  GLint ok = GL_FALSE;
  gl.GetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (ok) return shader;
  *log = shader_log(gl, shader);
  gl.DeleteShader(shader);
  return 0;
}

GLuint compile_fullscreen_vertex(const GlApi& gl, const std::string& shader_dir) {
  return compile_stage(gl, GL_VERTEX_SHADER, shader_dir, "common/fullscreen.vert", "");
}

GlProgram build_program(const GlApi& gl, const std::string& shader_dir, const GlProgramFiles& f) {
  GlProgram p;
  p.name = f.fragment;
  const GLuint vs = compile_stage(gl, GL_VERTEX_SHADER, shader_dir, f.vertex, f.defines);
  GLuint fs = 0;
  try {
    fs = compile_stage(gl, GL_FRAGMENT_SHADER, shader_dir, f.fragment, f.defines);
  } catch (...) {
    gl.DeleteShader(vs);
    throw;
  }
  p.id = gl.CreateProgram();
  gl.AttachShader(p.id, vs);
  gl.AttachShader(p.id, fs);
  gl.LinkProgram(p.id);
  GLint ok = GL_FALSE;
  gl.GetProgramiv(p.id, GL_LINK_STATUS, &ok);
  gl.DetachShader(p.id, vs);
  gl.DetachShader(p.id, fs);
  gl.DeleteShader(vs);
  gl.DeleteShader(fs);
  if (!ok) {
    const std::string log = program_log(gl, p.id);
    gl.DeleteProgram(p.id);
    throw ShaderError("cannot link " + f.vertex + " + " + f.fragment + ":\n" + log);
  }
  reflect_uniforms(gl, p);
  gl.check("linking " + f.fragment);
  return p;
}

int uniform_components(GLenum type) {
  switch (type) {
    case GL_FLOAT:
    case GL_INT:
    case GL_UNSIGNED_INT:
    case GL_BOOL:
      return 1;
    case GL_FLOAT_VEC2:
    case GL_INT_VEC2:
    case GL_UNSIGNED_INT_VEC2:
    case GL_BOOL_VEC2:
      return 2;
    case GL_FLOAT_VEC3:
    case GL_INT_VEC3:
    case GL_UNSIGNED_INT_VEC3:
    case GL_BOOL_VEC3:
      return 3;
    case GL_FLOAT_VEC4:
    case GL_INT_VEC4:
    case GL_UNSIGNED_INT_VEC4:
    case GL_BOOL_VEC4:
      return 4;
    case GL_FLOAT_MAT4:
      return 16;
    default:
      return 0;
  }
}

bool is_sampler(GLenum type) {
  switch (type) {
    case GL_SAMPLER_1D:
    case GL_SAMPLER_2D:
    case GL_SAMPLER_3D:
    case GL_SAMPLER_2D_ARRAY:
    case GL_SAMPLER_CUBE:
    case GL_INT_SAMPLER_2D:
    case GL_UNSIGNED_INT_SAMPLER_2D:
      return true;
    default:
      return false;
  }
}

}  // namespace sdfreel
