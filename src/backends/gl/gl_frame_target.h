#pragma once
// The float frame target every platform hands the driver: a framebuffer object with an RGBA32F
// colour renderbuffer and a 24-bit depth renderbuffer, reallocated when the size changes. It lives
// in the platform's context: make that current before any call, the destructor included.
#include <string>

#include "backends/gl/gl_platform.h"

namespace sdfreel {

class GlFrameTarget {
 public:
  // `platform` names the platform in error messages ("egl", "osmesa").
  GlFrameTarget(const GlApi& gl, std::string platform) : gl_(gl), platform_(std::move(platform)) {}
  ~GlFrameTarget() { release(); }
  GlFrameTarget(const GlFrameTarget&) = delete;
  GlFrameTarget& operator=(const GlFrameTarget&) = delete;

  GlTargetRef at_size(int width, int height);
  void release();
  // Forgets the GL objects without deleting them (their context is gone or cannot be made current).
  void abandon() { target_ = GlTargetRef{}, color_ = depth_ = 0; }

 private:
  const GlApi& gl_;
  std::string platform_;
  GlTargetRef target_;
  GLuint color_ = 0, depth_ = 0;  // renderbuffers of target_
};

}  // namespace sdfreel
