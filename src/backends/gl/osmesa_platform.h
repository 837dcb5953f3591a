#pragma once
// OSMesa platform: Mesa's software rasteriser (llvmpipe) with an OpenGL 4.5 core context and an
// RGBA32F framebuffer object. libOSMesa is opened at run time (dlopen), so an sdfreel built
// anywhere still starts, and renders on the CPU backend or through EGL, on a machine without the
// library; asking for this platform there is a clear GlPlatformError instead of a loader failure.
// Mesa 25.1 removed OSMesa: the EGL platform (egl_platform.h) is the default.
#include <memory>

#include "backends/gl/gl_frame_target.h"
#include "backends/gl/gl_platform.h"

namespace sdfreel {

class OsmesaPlatform : public GlPlatform {
 public:
  struct Library;  // libOSMesa's entry points, loaded once per process (osmesa_platform.cpp)

  // Opens the library (env SDFREEL_OSMESA_LIBRARY, default libOSMesa.so.8), creates the context
  // and makes it current. Throws GlPlatformError with the reason when any step fails.
  OsmesaPlatform();
  ~OsmesaPlatform() override;
  OsmesaPlatform(const OsmesaPlatform&) = delete;
  OsmesaPlatform& operator=(const OsmesaPlatform&) = delete;

  std::string name() const override { return "osmesa"; }
  void make_current() override;
  void release() override {}  // an OSMesa context may be made current on any thread
  std::string device() const override { return "software"; }
  const GlApi& gl() const override { return gl_; }
  GlTargetRef frame_target(int width, int height) override {
    return target_->at_size(width, height);
  }

 private:
  const Library* lib_;
  void* context_ = nullptr;  // OSMesaContext
  GlApi gl_;
  std::unique_ptr<GlFrameTarget> target_;
  bool try_make_current();
};

}  // namespace sdfreel
