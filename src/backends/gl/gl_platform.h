#pragma once
// The platform half of the GL backend (after Filament's Platform/Driver split): it owns a GL
// context and the float framebuffer object that frames are rendered into, and nothing else. The
// driver (gl_driver.h) runs passes through any platform: EGL (egl_platform.h, the default) or
// OSMesa (osmesa_platform.h, which Mesa 25.1 removed), with the same driver and shader code.
#include <stdexcept>
#include <string>

#include "backends/gl/gl_api.h"

namespace sdfreel {

// A platform that cannot start: no GL library, no context of the required version.
struct GlPlatformError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// A framebuffer object and its size. Attachment 0 is RGBA32F; the platform's frame target also
// has a 24-bit depth buffer, so mesh passes can depth-test straight into it.
struct GlTargetRef {
  GLuint framebuffer = 0;
  int width = 0, height = 0;
  int color_attachments = 1;  // RGBA32F, drawn to as fragment outputs 0..n-1
  bool depth = true;
};

class GlPlatform {
 public:
  virtual ~GlPlatform() = default;
  virtual std::string name() const = 0;  // "egl", "osmesa"
  // Makes the context current on the calling thread (call before any GL work on that thread).
  virtual void make_current() = 0;
  // Releases the context from the calling thread, so that another thread may make it current
  // (EGL allows a context current on one thread at a time).
  virtual void release() = 0;
  // The device the context runs on, as `sdfreel devices` names it ("software" for llvmpipe).
  virtual std::string device() const = 0;
  // GL entry points of the context, loaded once.
  virtual const GlApi& gl() const = 0;
  // The float frame target at width x height, reallocated when the size changes. Needs the
  // context current.
  virtual GlTargetRef frame_target(int width, int height) = 0;
};

}  // namespace sdfreel
