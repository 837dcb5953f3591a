#include "backends/gl/osmesa_platform.h"

#include <dlfcn.h>

#include <cstdlib>

namespace sdfreel {

namespace {

// The few declarations of GL/osmesa.h that sdfreel uses (a stable ABI since Mesa 11), so the
// backend builds on releases whose Mesa no longer ships the header.
using OSMesaContext = struct osmesa_context*;
using OSMESAproc = void (*)();
constexpr int OSMESA_FORMAT = 0x22, OSMESA_DEPTH_BITS = 0x30, OSMESA_STENCIL_BITS = 0x31,
              OSMESA_PROFILE = 0x33, OSMESA_CORE_PROFILE = 0x34,
              OSMESA_CONTEXT_MAJOR_VERSION = 0x36, OSMESA_CONTEXT_MINOR_VERSION = 0x37;

constexpr const char* DEFAULT_LIBRARY = "libOSMesa.so.8";

// OSMesa needs a colour buffer to make a context current; frames go to the framebuffer object,
// so a single pixel suffices.
unsigned char dummy_buffer[4];

}  // namespace

// The library's entry points. It is opened once and never closed: unloading a library that
// carries LLVM while its atexit handlers are registered is a classic crash at exit.
struct OsmesaPlatform::Library {
  OSMesaContext (*create)(const int*, OSMesaContext) = nullptr;
  GLboolean (*make_current)(OSMesaContext, void*, GLenum, GLsizei, GLsizei) = nullptr;
  void (*destroy)(OSMesaContext) = nullptr;
  OSMESAproc (*get_proc)(const char*) = nullptr;
  std::string error;  // why the library could not be used; empty when it can
};

namespace {

template <typename F>
void bind(void* handle, const char* name, F& fn, const std::string& path) {
  fn = reinterpret_cast<F>(dlsym(handle, name));
  if (!fn) throw GlPlatformError("OSMesa: " + path + " has no " + name);
}

OsmesaPlatform::Library load_library() {
  OsmesaPlatform::Library lib;
  const char* env = std::getenv("SDFREEL_OSMESA_LIBRARY");
  const std::string path = env && *env ? env : DEFAULT_LIBRARY;
  try {
    void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle)
      throw GlPlatformError("OSMesa is not available: cannot load " + path + " (" + dlerror() +
                            "); install libosmesa6 (Mesa 25.0 or older), or use the EGL "
                            "platform (--gl-platform egl) or --backend cpu");
    bind(handle, "OSMesaCreateContextAttribs", lib.create, path);
    bind(handle, "OSMesaMakeCurrent", lib.make_current, path);
    bind(handle, "OSMesaDestroyContext", lib.destroy, path);
    bind(handle, "OSMesaGetProcAddress", lib.get_proc, path);
  } catch (const GlPlatformError& e) {
    lib.error = e.what();
  }
  return lib;
}

const OsmesaPlatform::Library& osmesa_library() {
  static const OsmesaPlatform::Library lib = load_library();  // once, thread-safe
  if (!lib.error.empty()) throw GlPlatformError(lib.error);
  return lib;
}

}  // namespace

OsmesaPlatform::OsmesaPlatform() : lib_(&osmesa_library()) {
  // clang-format off
  const int attribs[] = {OSMESA_FORMAT, GL_RGBA,
                         OSMESA_DEPTH_BITS, 0,  // depth lives in the framebuffer object
                         OSMESA_STENCIL_BITS, 0,
                         OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                         OSMESA_CONTEXT_MAJOR_VERSION, 4,
                         OSMESA_CONTEXT_MINOR_VERSION, 5,
                         0};
  // clang-format on
  context_ = lib_->create(attribs, nullptr);
  if (!context_)
    throw GlPlatformError(
        "OSMesa could not create an OpenGL 4.5 core context (Mesa too old, or "
        "a driver other than llvmpipe/softpipe selected by GALLIUM_DRIVER?)");
  make_current();
  try {
    gl_.load([this](const char* name) { return reinterpret_cast<void*>(lib_->get_proc(name)); });
  } catch (const std::exception& e) {
    lib_->destroy(static_cast<OSMesaContext>(context_));
    throw GlPlatformError(std::string("OSMesa: ") + e.what());
  }
  target_ = std::make_unique<GlFrameTarget>(gl_, name());
}

OsmesaPlatform::~OsmesaPlatform() {
  // GL objects can only be deleted in their context; if it cannot be made current, destroying
  // the context frees them anyway.
  if (!try_make_current()) target_->abandon();
  target_.reset();
  lib_->destroy(static_cast<OSMesaContext>(context_));
}

bool OsmesaPlatform::try_make_current() {
  return lib_->make_current(static_cast<OSMesaContext>(context_), dummy_buffer, GL_UNSIGNED_BYTE, 1,
                            1);
}

void OsmesaPlatform::make_current() {
  if (!try_make_current()) throw GlPlatformError("OSMesaMakeCurrent failed");
}

}  // namespace sdfreel
