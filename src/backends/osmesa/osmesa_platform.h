#pragma once
// OSMesa platform: Mesa's software rasteriser (llvmpipe) with an OpenGL 4.5 core context and an
// RGBA32F framebuffer object. libOSMesa is opened at run time (dlopen), so an sdfreel built with
// OSMesa headers still starts, and renders on the CPU backend, on a machine without the library;
// asking for this platform there is a clear GlPlatformError instead of a loader failure.
#include "backends/osmesa/gl_platform.h"

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
  const GlApi& gl() const override { return gl_; }
  GlTargetRef frame_target(int width, int height) override;

 private:
  const Library* lib_;
  void* context_ = nullptr;  // OSMesaContext
  GlApi gl_;
  GlTargetRef target_;
  GLuint color_ = 0, depth_ = 0;  // renderbuffers of target_
  void release_target();
};

}  // namespace sdfreel
