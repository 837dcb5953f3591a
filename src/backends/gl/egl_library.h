#pragma once
// libEGL.so.1 (libglvnd's dispatcher) opened at run time: sdfreel links no GL library, so it
// starts, and renders on the CPU, on a machine without one. Only eglGetProcAddress is looked up
// with dlsym; every other EGL function, extension or core, comes through it, as do the GL
// functions of a context (GlApi::load).
#define EGL_NO_X11  // no window system: keep X11's headers out of eglplatform.h
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <string>

namespace sdfreel {

// X(type, name): one line per EGL entry point sdfreel calls.
#define SDFREEL_EGL_FUNCTIONS(X)                            \
  X(PFNEGLGETERRORPROC, GetError)                           \
  X(PFNEGLQUERYSTRINGPROC, QueryString)                     \
  X(PFNEGLGETPLATFORMDISPLAYEXTPROC, GetPlatformDisplayEXT) \
  X(PFNEGLINITIALIZEPROC, Initialize)                       \
  X(PFNEGLBINDAPIPROC, BindAPI)                             \
  X(PFNEGLCHOOSECONFIGPROC, ChooseConfig)                   \
  X(PFNEGLCREATECONTEXTPROC, CreateContext)                 \
  X(PFNEGLDESTROYCONTEXTPROC, DestroyContext)               \
  X(PFNEGLCREATEPBUFFERSURFACEPROC, CreatePbufferSurface)   \
  X(PFNEGLDESTROYSURFACEPROC, DestroySurface)               \
  X(PFNEGLMAKECURRENTPROC, MakeCurrent)                     \
  X(PFNEGLGETCURRENTCONTEXTPROC, GetCurrentContext)

// Present only where the client extensions EGL_EXT_device_enumeration / _query are.
#define SDFREEL_EGL_DEVICE_FUNCTIONS(X)                   \
  X(PFNEGLQUERYDEVICESEXTPROC, QueryDevicesEXT)           \
  X(PFNEGLQUERYDEVICESTRINGEXTPROC, QueryDeviceStringEXT) \
  X(PFNEGLQUERYDEVICEATTRIBEXTPROC, QueryDeviceAttribEXT)

struct EglLibrary {
#define SDFREEL_EGL_DECLARE(type, name) type name = nullptr;
  SDFREEL_EGL_FUNCTIONS(SDFREEL_EGL_DECLARE)
  SDFREEL_EGL_DEVICE_FUNCTIONS(SDFREEL_EGL_DECLARE)
#undef SDFREEL_EGL_DECLARE
  PFNEGLGETPROCADDRESSPROC GetProcAddress = nullptr;
  bool has_devices() const {
    return QueryDevicesEXT && QueryDeviceStringEXT;
  }
  // Whether the space-separated extension list `list` names `ext`.
  static bool has_extension(const char* list, const char* ext);
  // EGL_SUCCESS, EGL_BAD_ACCESS... as text, for error messages.
  std::string last_error() const;
};

// The process's library (env SDFREEL_EGL_LIBRARY, default libEGL.so.1), loaded once and never
// closed. Throws GlPlatformError (gl_platform.h) when it is missing or lacks a core function.
const EglLibrary& egl_library();

}  // namespace sdfreel
