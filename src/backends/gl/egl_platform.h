#pragma once
// EGL platform: no display server, no window. The display is the EGL device platform
// (EGL_EXT_platform_device) on the chosen device, else Mesa's surfaceless platform; the context is
// OpenGL 4.5 core, made current without a surface where EGL_KHR_surfaceless_context allows and on
// a 1x1 pbuffer elsewhere; frames go to the driver's framebuffer objects as on OSMesa. The default
// device is Mesa's software one (llvmpipe), whose frames have the OSMesa platform's bits; a GPU
// is used only when asked for (egl_devices.h), never as a silent fallback.
#include <memory>

#include "backends/gl/egl_library.h"
#include "backends/gl/gl_frame_target.h"
#include "backends/gl/gl_platform.h"

namespace sdfreel {

class EglPlatform : public GlPlatform {
 public:
  // `device`: software, gpu or an index (egl_devices.h). Creates the context and makes it current
  // on the calling thread; throws GlPlatformError with the reason when any step fails.
  explicit EglPlatform(const std::string& device = "software");
  ~EglPlatform() override;
  EglPlatform(const EglPlatform&) = delete;
  EglPlatform& operator=(const EglPlatform&) = delete;

  std::string name() const override { return "egl"; }
  void make_current() override;
  void release() override;
  std::string device() const override { return device_; }
  const GlApi& gl() const override { return gl_; }
  GlTargetRef frame_target(int width, int height) override {
    return target_->at_size(width, height);
  }

 private:
  const EglLibrary& egl_;
  EGLDisplay display_ = EGL_NO_DISPLAY;
  EGLContext context_ = EGL_NO_CONTEXT;
  EGLSurface surface_ = EGL_NO_SURFACE;  // the 1x1 pbuffer, where surfaceless is not offered
  std::string device_;
  bool software_ = false;  // Mesa's software device: the renderer must be llvmpipe
  GlApi gl_;
  std::unique_ptr<GlFrameTarget> target_;
  void open_display(const std::string& device);
  void create_context();
  void destroy();
};

}  // namespace sdfreel
