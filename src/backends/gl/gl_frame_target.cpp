#include "backends/gl/gl_frame_target.h"

namespace sdfreel {

void GlFrameTarget::release() {
  if (target_.framebuffer) gl_.DeleteFramebuffers(1, &target_.framebuffer);
  if (color_) gl_.DeleteRenderbuffers(1, &color_);
  if (depth_) gl_.DeleteRenderbuffers(1, &depth_);
  abandon();
}

GlTargetRef GlFrameTarget::at_size(int width, int height) {
  if (target_.framebuffer && target_.width == width && target_.height == height) return target_;
  release();
  GLint max_size = 0;
  gl_.GetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &max_size);
  if (width < 1 || height < 1 || width > max_size || height > max_size)
    throw GlPlatformError(platform_ + ": a " + std::to_string(width) + "x" +
                          std::to_string(height) + " frame exceeds the renderer's limit of " +
                          std::to_string(max_size));
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
    release();
    throw GlPlatformError(platform_ + ": the RGBA32F frame target is incomplete (status " +
                          std::to_string(status) + ")");
  }
  gl_.check("creating the frame target");
  return target_;
}

}  // namespace sdfreel
