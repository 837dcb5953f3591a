#pragma once
// The OpenGL 4.5 core functions sdfreel calls, loaded at run time through the platform's
// get-proc-address. Nothing links against a GL library: the driver code works unchanged with any
// platform (OSMesa today, EGL surfaceless later), and a machine without one still runs the CPU
// backend. Call them as gl.DrawArrays(...).
#include <GL/glcorearb.h>

#include <functional>
#include <string>

namespace sdfreel {

// X(type, name): one line per GL entry point (without the gl prefix).
#define SDFREEL_GL_FUNCTIONS(X)                                \
  X(PFNGLGETSTRINGPROC, GetString)                             \
  X(PFNGLGETINTEGERVPROC, GetIntegerv)                         \
  X(PFNGLGETERRORPROC, GetError)                               \
  X(PFNGLENABLEPROC, Enable)                                   \
  X(PFNGLDISABLEPROC, Disable)                                 \
  X(PFNGLVIEWPORTPROC, Viewport)                               \
  X(PFNGLSCISSORPROC, Scissor)                                 \
  X(PFNGLFINISHPROC, Finish)                                   \
  X(PFNGLDEPTHFUNCPROC, DepthFunc)                             \
  X(PFNGLDEPTHMASKPROC, DepthMask)                             \
  X(PFNGLBLENDFUNCPROC, BlendFunc)                             \
  X(PFNGLBLENDEQUATIONPROC, BlendEquation)                     \
  X(PFNGLCULLFACEPROC, CullFace)                               \
  X(PFNGLFRONTFACEPROC, FrontFace)                             \
  X(PFNGLCLEARBUFFERFVPROC, ClearBufferfv)                     \
  X(PFNGLCLEARBUFFERFIPROC, ClearBufferfi)                     \
  X(PFNGLPIXELSTOREIPROC, PixelStorei)                         \
  X(PFNGLREADBUFFERPROC, ReadBuffer)                           \
  X(PFNGLREADPIXELSPROC, ReadPixels)                           \
  X(PFNGLDRAWBUFFERSPROC, DrawBuffers)                         \
  X(PFNGLCREATESHADERPROC, CreateShader)                       \
  X(PFNGLSHADERSOURCEPROC, ShaderSource)                       \
  X(PFNGLCOMPILESHADERPROC, CompileShader)                     \
  X(PFNGLGETSHADERIVPROC, GetShaderiv)                         \
  X(PFNGLGETSHADERINFOLOGPROC, GetShaderInfoLog)               \
  X(PFNGLDELETESHADERPROC, DeleteShader)                       \
  X(PFNGLCREATEPROGRAMPROC, CreateProgram)                     \
  X(PFNGLATTACHSHADERPROC, AttachShader)                       \
  X(PFNGLDETACHSHADERPROC, DetachShader)                       \
  X(PFNGLLINKPROGRAMPROC, LinkProgram)                         \
  X(PFNGLGETPROGRAMIVPROC, GetProgramiv)                       \
  X(PFNGLGETPROGRAMINFOLOGPROC, GetProgramInfoLog)             \
  X(PFNGLDELETEPROGRAMPROC, DeleteProgram)                     \
  X(PFNGLUSEPROGRAMPROC, UseProgram)                           \
  X(PFNGLGETACTIVEUNIFORMPROC, GetActiveUniform)               \
  X(PFNGLGETUNIFORMLOCATIONPROC, GetUniformLocation)           \
  X(PFNGLUNIFORM1FVPROC, Uniform1fv)                           \
  X(PFNGLUNIFORM2FVPROC, Uniform2fv)                           \
  X(PFNGLUNIFORM3FVPROC, Uniform3fv)                           \
  X(PFNGLUNIFORM4FVPROC, Uniform4fv)                           \
  X(PFNGLUNIFORM1IVPROC, Uniform1iv)                           \
  X(PFNGLUNIFORM2IVPROC, Uniform2iv)                           \
  X(PFNGLUNIFORM3IVPROC, Uniform3iv)                           \
  X(PFNGLUNIFORM4IVPROC, Uniform4iv)                           \
  X(PFNGLUNIFORM1UIVPROC, Uniform1uiv)                         \
  X(PFNGLUNIFORM2UIVPROC, Uniform2uiv)                         \
  X(PFNGLUNIFORM3UIVPROC, Uniform3uiv)                         \
  X(PFNGLUNIFORM4UIVPROC, Uniform4uiv)                         \
  X(PFNGLUNIFORMMATRIX4FVPROC, UniformMatrix4fv)               \
  X(PFNGLGENVERTEXARRAYSPROC, GenVertexArrays)                 \
  X(PFNGLBINDVERTEXARRAYPROC, BindVertexArray)                 \
  X(PFNGLDELETEVERTEXARRAYSPROC, DeleteVertexArrays)           \
  X(PFNGLGENBUFFERSPROC, GenBuffers)                           \
  X(PFNGLBINDBUFFERPROC, BindBuffer)                           \
  X(PFNGLBUFFERDATAPROC, BufferData)                           \
  X(PFNGLDELETEBUFFERSPROC, DeleteBuffers)                     \
  X(PFNGLENABLEVERTEXATTRIBARRAYPROC, EnableVertexAttribArray) \
  X(PFNGLVERTEXATTRIBPOINTERPROC, VertexAttribPointer)         \
  X(PFNGLVERTEXATTRIBDIVISORPROC, VertexAttribDivisor)         \
  X(PFNGLDRAWARRAYSINSTANCEDPROC, DrawArraysInstanced)         \
  X(PFNGLDRAWELEMENTSINSTANCEDPROC, DrawElementsInstanced)     \
  X(PFNGLGENTEXTURESPROC, GenTextures)                         \
  X(PFNGLBINDTEXTUREPROC, BindTexture)                         \
  X(PFNGLACTIVETEXTUREPROC, ActiveTexture)                     \
  X(PFNGLTEXIMAGE2DPROC, TexImage2D)                           \
  X(PFNGLTEXPARAMETERIPROC, TexParameteri)                     \
  X(PFNGLDELETETEXTURESPROC, DeleteTextures)                   \
  X(PFNGLGENFRAMEBUFFERSPROC, GenFramebuffers)                 \
  X(PFNGLBINDFRAMEBUFFERPROC, BindFramebuffer)                 \
  X(PFNGLFRAMEBUFFERTEXTURE2DPROC, FramebufferTexture2D)       \
  X(PFNGLFRAMEBUFFERRENDERBUFFERPROC, FramebufferRenderbuffer) \
  X(PFNGLCHECKFRAMEBUFFERSTATUSPROC, CheckFramebufferStatus)   \
  X(PFNGLDELETEFRAMEBUFFERSPROC, DeleteFramebuffers)           \
  X(PFNGLGENRENDERBUFFERSPROC, GenRenderbuffers)               \
  X(PFNGLBINDRENDERBUFFERPROC, BindRenderbuffer)               \
  X(PFNGLRENDERBUFFERSTORAGEPROC, RenderbufferStorage)         \
  X(PFNGLDELETERENDERBUFFERSPROC, DeleteRenderbuffers)         \
  X(PFNGLUNIFORMMATRIX3FVPROC, UniformMatrix3fv)               \
  X(PFNGLGENERATEMIPMAPPROC, GenerateMipmap)                   \
  X(PFNGLGENSAMPLERSPROC, GenSamplers)                         \
  X(PFNGLBINDSAMPLERPROC, BindSampler)                         \
  X(PFNGLSAMPLERPARAMETERIPROC, SamplerParameteri)             \
  X(PFNGLDELETESAMPLERSPROC, DeleteSamplers)

struct GlApi {
#define SDFREEL_GL_DECLARE(type, name) type name = nullptr;
  SDFREEL_GL_FUNCTIONS(SDFREEL_GL_DECLARE)
#undef SDFREEL_GL_DECLARE

  using ProcAddress = std::function<void*(const char* name)>;
  // Fills every pointer through get_proc ("glDrawArrays", ...). Throws std::runtime_error naming
  // the first function the platform does not provide.
  void load(const ProcAddress& get_proc);

  // GL_VERSION / GL_RENDERER of the current context ("" when unavailable).
  std::string string(GLenum which) const;
  // Throws std::runtime_error("<what>: GL error 0x...") if the context has recorded an error.
  void check(const std::string& what) const;
};

}  // namespace sdfreel
