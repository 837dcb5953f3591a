#include "backends/gl/egl_library.h"

#include <dlfcn.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "backends/gl/gl_platform.h"

namespace sdfreel {

bool EglLibrary::has_extension(const char* list, const char* ext) {
  if (!list) return false;
  const size_t n = std::strlen(ext);
  for (const char* p = list; (p = std::strstr(p, ext)); p += n)
    if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
  return false;
}

std::string EglLibrary::last_error() const {
  const EGLint e = GetError();
  char code[16];
  std::snprintf(code, sizeof code, "0x%04x", unsigned(e));
  return std::string("EGL error ") + code;
}

namespace {

struct Loaded {
  EglLibrary lib;
  std::string error;  // why the library cannot be used; empty when it can
};

Loaded load() {
  Loaded l;
  const char* env = std::getenv("SDFREEL_EGL_LIBRARY");
  const std::string path = env && *env ? env : "libEGL.so.1";
  void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle) {
    l.error = "EGL is not available: cannot load " + path + " (" + dlerror() +
              "); install libegl1 and libegl-mesa0, or use --backend cpu";
    return l;
  }
  EglLibrary& lib = l.lib;
  lib.GetProcAddress =
      reinterpret_cast<PFNEGLGETPROCADDRESSPROC>(dlsym(handle, "eglGetProcAddress"));
  if (!lib.GetProcAddress) {
    l.error = "EGL: " + path + " has no eglGetProcAddress";
    return l;
  }
#define SDFREEL_EGL_LOAD(type, name) \
  lib.name = reinterpret_cast<type>(lib.GetProcAddress("egl" #name));
  SDFREEL_EGL_FUNCTIONS(SDFREEL_EGL_LOAD)
  SDFREEL_EGL_DEVICE_FUNCTIONS(SDFREEL_EGL_LOAD)
#undef SDFREEL_EGL_LOAD
#define SDFREEL_EGL_REQUIRE(type, name) \
  if (!lib.name && l.error.empty()) l.error = "EGL: " + path + " provides no egl" #name;
  SDFREEL_EGL_FUNCTIONS(SDFREEL_EGL_REQUIRE)
#undef SDFREEL_EGL_REQUIRE
  return l;
}

}  // namespace

const EglLibrary& egl_library() {
  static const Loaded loaded = load();  // once, thread-safe
  if (!loaded.error.empty()) throw GlPlatformError(loaded.error);
  return loaded.lib;
}

}  // namespace sdfreel
