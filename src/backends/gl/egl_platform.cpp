#include "backends/gl/egl_platform.h"

#include "backends/gl/egl_devices.h"

namespace sdfreel {

namespace {

bool is_software_renderer(const std::string& renderer) {
  return renderer.rfind("llvmpipe", 0) == 0 || renderer.rfind("softpipe", 0) == 0;
}

}  // namespace

EglPlatform::EglPlatform(const std::string& device) : egl_(egl_library()) {
  open_display(device);
  try {
    create_context();
    make_current();
    try {
      gl_.load([this](const char* n) { return reinterpret_cast<void*>(egl_.GetProcAddress(n)); });
    } catch (const std::exception& e) {
      throw GlPlatformError(std::string("EGL: ") + e.what());
    }
    // Mesa's loader may pick another driver for a display (zink, a GPU behind the surfaceless
    // platform): frames must come from the device that was asked for.
    const std::string renderer = gl_.string(GL_RENDERER);
    if (software_ && !is_software_renderer(renderer))
      throw GlPlatformError("EGL: the software device gave the renderer '" + renderer +
                            "', not llvmpipe (is GALLIUM_DRIVER or MESA_LOADER_DRIVER_OVERRIDE "
                            "set?)");
    target_ = std::make_unique<GlFrameTarget>(gl_, name());
  } catch (const GlPlatformError&) {
    destroy();
    throw;
  }
}

void EglPlatform::open_display(const std::string& device) {
  const char* client = egl_.QueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  const std::vector<EglDevice> devices = egl_devices(egl_);
  if (EglLibrary::has_extension(client, "EGL_EXT_platform_device") && !devices.empty()) {
    const EglDevice d = choose_egl_device(devices, device);
    display_ = egl_.GetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, d.handle, nullptr);
    // Software has no index in the name: a GPU listed first must not change a manifest's device.
    device_ = d.software ? "software" : std::to_string(d.index) + " " + d.name;
    software_ = d.software;
  } else if (EglLibrary::has_extension(client, "EGL_MESA_platform_surfaceless")) {
    // No device to choose: Mesa's surfaceless display, checked for llvmpipe after creation.
    if (device != "software")
      throw GlPlatformError("EGL cannot enumerate devices here (no EGL_EXT_platform_device), so '" +
                            device + "' cannot be chosen; only the software device works");
    display_ =
        egl_.GetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    device_ = "software";
    software_ = true;
  } else {
    throw GlPlatformError(
        "EGL offers neither the device platform nor Mesa's surfaceless one (install "
        "libegl-mesa0, or use --gl-platform osmesa)");
  }
  EGLint major = 0, minor = 0;
  if (display_ == EGL_NO_DISPLAY || !egl_.Initialize(display_, &major, &minor))
    throw GlPlatformError("EGL: cannot initialise the display of device " + device_ + " (" +
                          egl_.last_error() + ")");
}

void EglPlatform::create_context() {
  const char* ext = egl_.QueryString(display_, EGL_EXTENSIONS);
  const bool surfaceless = EglLibrary::has_extension(ext, "EGL_KHR_surfaceless_context");
  if (!egl_.BindAPI(EGL_OPENGL_API))
    throw GlPlatformError("EGL: the device offers no desktop OpenGL (" + egl_.last_error() + ")");
  // clang-format off
  const EGLint config_attribs[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT,
                                   EGL_SURFACE_TYPE, surfaceless ? 0 : EGL_PBUFFER_BIT,
                                   EGL_NONE};
  const EGLint context_attribs[] = {EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, 5,
                                    EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                    EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                    EGL_NONE};
  // clang-format on
  EGLConfig config = nullptr;
  EGLint count = 0;
  if (!egl_.ChooseConfig(display_, config_attribs, &config, 1, &count) || count < 1)
    throw GlPlatformError("EGL: device " + device_ + " has no OpenGL configuration");
  context_ = egl_.CreateContext(display_, config, EGL_NO_CONTEXT, context_attribs);
  if (context_ == EGL_NO_CONTEXT)
    throw GlPlatformError("EGL: device " + device_ + " cannot create an OpenGL 4.5 core context (" +
                          egl_.last_error() + ")");
  if (surfaceless) return;
  const EGLint pbuffer_attribs[] = {EGL_WIDTH, 1, EGL_HEIGHT, 1, EGL_NONE};
  surface_ = egl_.CreatePbufferSurface(display_, config, pbuffer_attribs);
  if (surface_ == EGL_NO_SURFACE)
    throw GlPlatformError("EGL: no surfaceless contexts and no 1x1 pbuffer on device " + device_ +
                          " (" + egl_.last_error() + ")");
}

void EglPlatform::make_current() {
  if (egl_.GetCurrentContext() == context_) return;
  if (!egl_.MakeCurrent(display_, surface_, surface_, context_))
    throw GlPlatformError("EGL: cannot make the context current on this thread (" +
                          egl_.last_error() + "; is it current on another thread?)");
}

void EglPlatform::release() {
  if (egl_.GetCurrentContext() == context_)
    egl_.MakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
}

// GL objects are deleted in their context; the display stays initialised until the process ends
// (EGL does not count its users, and another platform may share it).
void EglPlatform::destroy() {
  if (target_) {
    try {
      make_current();
    } catch (const GlPlatformError&) {
      target_->abandon();  // destroying the context frees them
    }
    target_.reset();
  }
  release();
  if (surface_ != EGL_NO_SURFACE) egl_.DestroySurface(display_, surface_);
  if (context_ != EGL_NO_CONTEXT) egl_.DestroyContext(display_, context_);
  surface_ = EGL_NO_SURFACE;
  context_ = EGL_NO_CONTEXT;
}

EglPlatform::~EglPlatform() {
  destroy();
}

}  // namespace sdfreel
