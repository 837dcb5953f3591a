#include "backends/osmesa/osmesa_platform.h"

// glcorearb.h (through gl_api.h) must come before osmesa.h, which pulls in the legacy GL/gl.h.
#include <GL/osmesa.h>
#include <dlfcn.h>

#include <cstdlib>

namespace sdfreel {

namespace {

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
                            "); install libosmesa6 or use --backend cpu");
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
  const int attribs[] = {OSMESA_FORMAT, OSMESA_RGBA,
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
}

OsmesaPlatform::~OsmesaPlatform() {
  // GL objects can only be deleted in their context; if it cannot be made current, destroying
  // the context frees them anyway.
  if (lib_->make_current(static_cast<OSMesaContext>(context_), dummy_buffer, GL_UNSIGNED_BYTE, 1,
                         1))
    release_target();
  lib_->destroy(static_cast<OSMesaContext>(context_));
}

void OsmesaPlatform::make_current() {
  if (!lib_->make_current(static_cast<OSMesaContext>(context_), dummy_buffer, GL_UNSIGNED_BYTE, 1,
                          1))
    throw GlPlatformError("OSMesaMakeCurrent failed");
}

void OsmesaPlatform::release_target() {
  if (target_.framebuffer) gl_.DeleteFramebuffers(1, &target_.framebuffer);
  if (color_) gl_.DeleteRenderbuffers(1, &color_);
  if (depth_) gl_.DeleteRenderbuffers(1, &depth_);
  target_ = GlTargetRef{};
  color_ = depth_ = 0;
}

GlTargetRef OsmesaPlatform::frame_target(int width, int height) {
  if (target_.framebuffer && target_.width == width && target_.height == height) return target_;
  release_target();
  GLint max_size = 0;
  gl_.GetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &max_size);
  if (width < 1 || height < 1 || width > max_size || height > max_size)
    throw GlPlatformError("OSMesa: a " + std::to_string(width) + "x" + std::to_string(height) +
                          " frame exceeds the renderer's limit of " + std::to_string(max_size));
  gl_.GenFramebuffers(1, &target_.framebuffer);
  gl_.BindFramebuffer(GL_FRAMEBUFFER, target_.framebuffer);
  gl_.GenRenderbuffers(1, &color_);
  gl_.BindRenderbuffer(GL_RENDERBUFFER, color_);
  gl_.RenderbufferStorage(GL_RENDERBUFFER, GL_RGBA32F, width, height);
  gl_.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color_);
  gl_.GenRenderbuffers(1, &depth_);
  gl_.BindRenderbuffer(GL_RENDERBUFFER, depth_);
  gl_.RenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width, height);
  gl_.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_);
  const GLenum status = gl_.CheckFramebufferStatus(GL_FRAMEBUFFER);
  target_.width = width;
  target_.height = height;
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    release_target();
    throw GlPlatformError("OSMesa: the RGBA32F frame target is incomplete (status " +
                          std::to_string(status) + ")");
  }
  gl_.check("creating the frame target");
  return target_;
}

}  // namespace sdfreel
