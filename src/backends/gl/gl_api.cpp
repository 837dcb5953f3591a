#include "backends/gl/gl_api.h"

#include <cstdio>
#include <stdexcept>

namespace sdfreel {

void GlApi::load(const ProcAddress& get_proc) {
#define SDFREEL_GL_LOAD(type, name)                                      \
  name = reinterpret_cast<type>(get_proc("gl" #name));                   \
  if (!name)                                                             \
    throw std::runtime_error("the GL platform does not provide gl" #name \
                             " (OpenGL "                                 \
                             "4.5 core is required)");
  SDFREEL_GL_FUNCTIONS(SDFREEL_GL_LOAD)
#undef SDFREEL_GL_LOAD
}

std::string GlApi::string(GLenum which) const {
  const GLubyte* s = GetString ? GetString(which) : nullptr;
  return s ? reinterpret_cast<const char*>(s) : "";
}

void GlApi::check(const std::string& what) const {
  const GLenum err = GetError();
  if (err == GL_NO_ERROR) return;
  char code[16];
  std::snprintf(code, sizeof code, "0x%04x", unsigned(err));
  throw std::runtime_error(what + ": GL error " + code);
}

}  // namespace sdfreel
