#include "backends/gl/gl_driver.h"

#include <algorithm>
#include <cstring>
#include <set>

namespace sdfreel {

namespace {

const char* type_name(GLenum type) {
  switch (type) {
    case GL_FLOAT:
      return "float";
    case GL_FLOAT_VEC2:
      return "vec2";
    case GL_FLOAT_VEC3:
      return "vec3";
    case GL_FLOAT_VEC4:
      return "vec4";
    case GL_INT:
      return "int";
    case GL_INT_VEC2:
      return "ivec2";
    case GL_INT_VEC3:
      return "ivec3";
    case GL_INT_VEC4:
      return "ivec4";
    case GL_UNSIGNED_INT:
      return "uint";
    case GL_BOOL:
      return "bool";
    case GL_FLOAT_MAT4:
      return "mat4";
    default:
      return "an unsupported type";
  }
}

enum class Scalar { Float, Int, Uint, Matrix };

Scalar scalar_kind(GLenum type) {
  switch (type) {
    case GL_INT:
    case GL_INT_VEC2:
    case GL_INT_VEC3:
    case GL_INT_VEC4:
    case GL_BOOL:
    case GL_BOOL_VEC2:
    case GL_BOOL_VEC3:
    case GL_BOOL_VEC4:
      return Scalar::Int;
    case GL_UNSIGNED_INT:
    case GL_UNSIGNED_INT_VEC2:
    case GL_UNSIGNED_INT_VEC3:
    case GL_UNSIGNED_INT_VEC4:
      return Scalar::Uint;
    case GL_FLOAT_MAT4:
      return Scalar::Matrix;
    default:
      return Scalar::Float;
  }
}

GLuint texture_format(int channels, GLenum& format) {
  switch (channels) {
    case 1:
      format = GL_RED;
      return GL_R32F;
    case 2:
      format = GL_RG;
      return GL_RG32F;
    case 3:
      format = GL_RGB;
      return GL_RGB32F;
    default:
      format = GL_RGBA;
      return GL_RGBA32F;
  }
}

}  // namespace

GlDriver::GlDriver(GlPlatform& platform, std::string shader_dir)
    : gl_(platform.gl()), shader_dir_(std::move(shader_dir)) {
  gl_.GenVertexArrays(1, &empty_vao_);
}

GlDriver::~GlDriver() {
  for (const GlProgram& p : programs_) gl_.DeleteProgram(p.id);
  for (MeshBuffers& m : meshes_) {
    gl_.DeleteVertexArrays(1, &m.vao);
    gl_.DeleteBuffers(5, m.buffers);
  }
  for (auto& [name, tex] : textures_) gl_.DeleteTextures(1, &tex);
  for (GlRenderTarget& t : targets_) {
    gl_.DeleteFramebuffers(1, &t.ref.framebuffer);
    gl_.DeleteTextures(GLsizei(t.color_textures.size()), t.color_textures.data());
    if (t.depth_buffer) gl_.DeleteRenderbuffers(1, &t.depth_buffer);
  }
  gl_.DeleteVertexArrays(1, &empty_vao_);
}

GlProgramId GlDriver::compile(const GlProgramFiles& files) {
  programs_.push_back(build_program(gl_, shader_dir_, files));
  return GlProgramId(programs_.size() - 1);
}

GlMeshId GlDriver::create_mesh(const GlMesh& mesh) {
  if (mesh.positions.empty() || mesh.positions.size() % 3 != 0)
    throw std::invalid_argument("GlMesh: positions must be non-empty xyz triples");
  MeshBuffers m;
  gl_.GenVertexArrays(1, &m.vao);
  gl_.BindVertexArray(m.vao);
  gl_.GenBuffers(5, m.buffers);
  auto attribute = [&](GLuint index, const std::vector<float>& data, int size) {
    if (data.empty()) return;
    gl_.BindBuffer(GL_ARRAY_BUFFER, m.buffers[index]);
    gl_.BufferData(GL_ARRAY_BUFFER, GLsizeiptr(data.size() * sizeof(float)), data.data(),
                   GL_STATIC_DRAW);
    gl_.EnableVertexAttribArray(index);
    gl_.VertexAttribPointer(index, size, GL_FLOAT, GL_FALSE, 0, nullptr);
  };
  attribute(0, mesh.positions, 3);
  attribute(1, mesh.normals, 3);
  attribute(2, mesh.uvs, 2);
  m.indexed = !mesh.indices.empty();
  if (m.indexed) {
    gl_.BindBuffer(GL_ELEMENT_ARRAY_BUFFER, m.buffers[3]);
    gl_.BufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(mesh.indices.size() * sizeof(unsigned)),
                   mesh.indices.data(), GL_STATIC_DRAW);
  }
  m.count = GLsizei(m.indexed ? mesh.indices.size() : mesh.positions.size() / 3);
  // One identity instance until set_instances: a mesh draws where its vertices are.
  const float identity[20] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0};
  gl_.BindBuffer(GL_ARRAY_BUFFER, m.buffers[4]);
  gl_.BufferData(GL_ARRAY_BUFFER, sizeof identity, identity, GL_DYNAMIC_DRAW);
  for (GLuint a = 0; a < 5; ++a) {
    gl_.EnableVertexAttribArray(3 + a);
    gl_.VertexAttribPointer(3 + a, 4, GL_FLOAT, GL_FALSE, 20 * sizeof(float),
                            reinterpret_cast<const void*>(size_t(a) * 4 * sizeof(float)));
    gl_.VertexAttribDivisor(3 + a, 1);
  }
  gl_.BindVertexArray(0);
  gl_.check("creating a mesh");
  meshes_.push_back(m);
  return GlMeshId(meshes_.size() - 1);
}

void GlDriver::set_instances(GlMeshId mesh, const std::vector<float>& per_instance) {
  if (per_instance.empty() || per_instance.size() % 20 != 0)
    throw std::invalid_argument("set_instances: 20 floats an instance");
  const MeshBuffers& m = meshes_.at(size_t(mesh));
  gl_.BindBuffer(GL_ARRAY_BUFFER, m.buffers[4]);
  gl_.BufferData(GL_ARRAY_BUFFER, GLsizeiptr(per_instance.size() * sizeof(float)),
                 per_instance.data(), GL_DYNAMIC_DRAW);
  gl_.check("setting instances");
}

GLuint GlDriver::upload_texture(const ShaderTexture& t) {
  if (t.width < 1 || t.height < 1 || t.channels < 1 || t.channels > 4 ||
      t.texels.size() != size_t(t.width) * t.height * t.channels)
    throw std::invalid_argument("texture '" + t.name + "': size does not match its texels");
  GLuint& tex = textures_[t.name];
  if (!tex) gl_.GenTextures(1, &tex);
  gl_.BindTexture(GL_TEXTURE_2D, tex);
  GLenum format = GL_RGBA;
  const GLuint internal = texture_format(t.channels, format);
  gl_.PixelStorei(GL_UNPACK_ALIGNMENT, 4);
  // Row 0 of the texels goes to texel row 0: texelFetch(s, ivec2(x, y)) reads texels[y][x].
  gl_.TexImage2D(GL_TEXTURE_2D, 0, GLint(internal), t.width, t.height, 0, format, GL_FLOAT,
                 t.texels.data());
  gl_.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  gl_.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  gl_.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  gl_.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  gl_.check("uploading texture '" + t.name + "'");
  return tex;
}

const GlRenderTarget& GlDriver::create_render_target(int width, int height, int colors,
                                                     bool depth) {
  GlRenderTarget t;
  t.ref.width = width;
  t.ref.height = height;
  t.ref.color_attachments = colors;
  t.ref.depth = depth;
  gl_.GenFramebuffers(1, &t.ref.framebuffer);
  gl_.BindFramebuffer(GL_FRAMEBUFFER, t.ref.framebuffer);
  t.color_textures.resize(size_t(colors));
  gl_.GenTextures(colors, t.color_textures.data());
  for (int i = 0; i < colors; ++i) {
    gl_.BindTexture(GL_TEXTURE_2D, t.color_textures[size_t(i)]);
    gl_.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, width, height, 0, GL_RGBA, GL_FLOAT, nullptr);
    gl_.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    gl_.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    gl_.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0 + GLenum(i), GL_TEXTURE_2D,
                             t.color_textures[size_t(i)], 0);
  }
  if (depth) {
    gl_.GenRenderbuffers(1, &t.depth_buffer);
    gl_.BindRenderbuffer(GL_RENDERBUFFER, t.depth_buffer);
    gl_.RenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width, height);
    gl_.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER,
                                t.depth_buffer);
  }
  targets_.push_back(t);  // owned from here on, even if the check below throws
  if (gl_.CheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
    throw std::runtime_error("an off-screen render target is incomplete");
  gl_.check("creating a render target");
  return targets_.back();
}

void GlDriver::set_uniforms(const GlPass& pass, const GlProgram& prog) {
  std::set<std::string> given;
  for (const ShaderUniform& u : pass.uniforms) {
    const auto it = prog.uniforms.find(u.name);
    if (it == prog.uniforms.end()) continue;  // not used by this program (or optimised away)
    const GlUniformInfo& info = it->second;
    const int comps = uniform_components(info.type);
    const std::string where = "pass '" + pass.name + "', uniform '" + u.name + "' of " + prog.name;
    if (comps == 0 || is_sampler(info.type))
      throw ShaderError(where + ": is " + type_name(info.type) + ", not settable as numbers");
    const size_t n = u.values.size() / size_t(comps);
    if (u.components != comps || u.values.size() % size_t(comps) != 0 || n < 1 ||
        n > size_t(info.size))
      throw ShaderError(where + ": declared " + type_name(info.type) +
                        (info.size > 1 ? "[" + std::to_string(info.size) + "]" : "") + ", given " +
                        std::to_string(u.values.size()) + " values of " +
                        std::to_string(u.components) + " components");
    const GLsizei count = GLsizei(n);
    const Scalar kind = scalar_kind(info.type);
    if (kind == Scalar::Float) {
      const float* v = u.values.data();
      if (comps == 1) gl_.Uniform1fv(info.location, count, v);
      if (comps == 2) gl_.Uniform2fv(info.location, count, v);
      if (comps == 3) gl_.Uniform3fv(info.location, count, v);
      if (comps == 4) gl_.Uniform4fv(info.location, count, v);
    } else if (kind == Scalar::Matrix) {
      gl_.UniformMatrix4fv(info.location, count, GL_FALSE, u.values.data());
    } else if (kind == Scalar::Int) {
      std::vector<GLint> v(u.values.begin(), u.values.end());
      if (comps == 1) gl_.Uniform1iv(info.location, count, v.data());
      if (comps == 2) gl_.Uniform2iv(info.location, count, v.data());
      if (comps == 3) gl_.Uniform3iv(info.location, count, v.data());
      if (comps == 4) gl_.Uniform4iv(info.location, count, v.data());
    } else {
      std::vector<GLuint> v;
      for (float f : u.values) v.push_back(GLuint(f < 0.0f ? 0.0f : f));
      if (comps == 1) gl_.Uniform1uiv(info.location, count, v.data());
      if (comps == 2) gl_.Uniform2uiv(info.location, count, v.data());
      if (comps == 3) gl_.Uniform3uiv(info.location, count, v.data());
      if (comps == 4) gl_.Uniform4uiv(info.location, count, v.data());
    }
    given.insert(u.name);
  }
  int unit = 0;
  for (const GlTextureBinding& b : pass.textures) {
    const auto it = prog.uniforms.find(b.sampler);
    if (it == prog.uniforms.end()) continue;
    if (!is_sampler(it->second.type))
      throw ShaderError("pass '" + pass.name + "': '" + b.sampler + "' of " + prog.name +
                        " is not a sampler");
    gl_.ActiveTexture(GL_TEXTURE0 + GLenum(unit));
    gl_.BindTexture(GL_TEXTURE_2D, b.texture);
    const GLint u = unit++;
    gl_.Uniform1iv(it->second.location, 1, &u);
    given.insert(b.sampler);
  }
  for (const auto& [name, info] : prog.uniforms)
    if (!given.count(name))
      throw ShaderError("pass '" + pass.name + "': " + prog.name + " reads uniform '" + name +
                        "' but the pass gives it no value");
}

void GlDriver::draw(const GlPass& pass) {
  const int instances = std::max(1, pass.instances);
  if (pass.mesh == FULL_SCREEN_TRIANGLE) {
    gl_.BindVertexArray(empty_vao_);
    gl_.DrawArraysInstanced(GL_TRIANGLES, 0, 3, instances);
  } else {
    const MeshBuffers& m = meshes_.at(size_t(pass.mesh));
    gl_.BindVertexArray(m.vao);
    if (m.indexed)
      gl_.DrawElementsInstanced(GL_TRIANGLES, m.count, GL_UNSIGNED_INT, nullptr, instances);
    else
      gl_.DrawArraysInstanced(GL_TRIANGLES, 0, m.count, instances);
  }
  gl_.BindVertexArray(0);
}

void GlDriver::run(const GlPass& pass) {
  const GlProgram& prog = programs_.at(size_t(pass.program));
  const GlTargetRef& t = pass.target;
  gl_.BindFramebuffer(GL_FRAMEBUFFER, t.framebuffer);
  std::vector<GLenum> outputs;
  for (int i = 0; i < t.color_attachments; ++i) outputs.push_back(GL_COLOR_ATTACHMENT0 + GLenum(i));
  gl_.DrawBuffers(GLsizei(outputs.size()), outputs.data());
  gl_.Viewport(0, 0, t.width, t.height);
  if (pass.clear) {
    gl_.DepthMask(GL_TRUE);  // clearing depth obeys the depth mask
    for (int i = 0; i < t.color_attachments; ++i)
      gl_.ClearBufferfv(GL_COLOR, i, pass.clear_color.data());
    const float far = 1.0f;
    if (t.depth) gl_.ClearBufferfv(GL_DEPTH, 0, &far);
  }
  if (pass.depth == DepthMode::Off) {
    gl_.Disable(GL_DEPTH_TEST);
  } else {
    gl_.Enable(GL_DEPTH_TEST);
    gl_.DepthFunc(pass.depth == DepthMode::Always ? GL_ALWAYS : GL_LESS);
    gl_.DepthMask(pass.depth == DepthMode::TestOnly ? GL_FALSE : GL_TRUE);
  }
  if (pass.cull == GlCull::None) {
    gl_.Disable(GL_CULL_FACE);
  } else {
    gl_.Enable(GL_CULL_FACE);
    gl_.FrontFace(GL_CCW);
    gl_.CullFace(pass.cull == GlCull::Back ? GL_BACK : GL_FRONT);
  }
  if (pass.blend == BlendMode::Replace) {
    gl_.Disable(GL_BLEND);
  } else {
    gl_.Enable(GL_BLEND);
    gl_.BlendEquation(GL_FUNC_ADD);
    if (pass.blend == BlendMode::Add)
      gl_.BlendFunc(GL_ONE, GL_ONE);
    else
      gl_.BlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  }
  if (pass.scissor_rows > 0) {
    gl_.Enable(GL_SCISSOR_TEST);
    gl_.Scissor(0, pass.scissor_first_row, t.width, pass.scissor_rows);
  }
  gl_.UseProgram(prog.id);
  set_uniforms(pass, prog);
  draw(pass);
  gl_.Disable(GL_SCISSOR_TEST);  // clears elsewhere must reach every pixel
  gl_.check("pass '" + pass.name + "'");
}

ImageRGBA GlDriver::read_rgba(const GlTargetRef& target, int attachment) const {
  const int w = target.width, h = target.height;
  std::vector<float> rows(size_t(w) * h * 4);
  gl_.BindFramebuffer(GL_READ_FRAMEBUFFER, target.framebuffer);
  gl_.ReadBuffer(GL_COLOR_ATTACHMENT0 + GLenum(attachment));
  gl_.PixelStorei(GL_PACK_ALIGNMENT, 4);
  gl_.ReadPixels(0, 0, w, h, GL_RGBA, GL_FLOAT, rows.data());
  gl_.check("reading back the frame");
  ImageRGBA img(w, h);
  const size_t row_floats = size_t(w) * 4;
  for (int y = 0; y < h; ++y)
    std::memcpy(img.at(0, y), &rows[size_t(h - 1 - y) * row_floats], row_floats * sizeof(float));
  return img;
}

}  // namespace sdfreel
