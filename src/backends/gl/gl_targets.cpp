#include "backends/gl/gl_targets.h"

#include <stdexcept>

namespace sdfreel {

namespace {

bool same_specs(const std::vector<TargetSpec>& a, const std::vector<TargetSpec>& b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i)
    if (a[i].name != b[i].name || a[i].kind != b[i].kind || a[i].size != b[i].size) return false;
  return true;
}

}  // namespace

glm::ivec2 GlTargets::size_of(const TargetSpec& s) const {
  return s.size.x > 0 ? s.size : glm::ivec2(width_, height_);
}

void GlTargets::release() {
  for (auto& [key, fb] : framebuffers_) gl_.DeleteFramebuffers(1, &fb.framebuffer);
  for (auto& [name, tex] : textures_) gl_.DeleteTextures(1, &tex);
  framebuffers_.clear();
  textures_.clear();
}

void GlTargets::prepare(const std::vector<TargetSpec>& specs, int width, int height) {
  if (width == width_ && height == height_ && same_specs(specs, specs_)) {
    specs_ = specs;  // clear values may change from frame to frame
    return;
  }
  release();
  width_ = width;
  height_ = height;
  specs_ = specs;
  for (const TargetSpec& s : specs_) {
    GLuint& tex = textures_[s.name];
    gl_.GenTextures(1, &tex);
    gl_.BindTexture(GL_TEXTURE_2D, tex);
    const bool depth = s.kind == TargetKind::Depth;
    const glm::ivec2 size = size_of(s);
    gl_.TexImage2D(GL_TEXTURE_2D, 0, depth ? GL_DEPTH_COMPONENT32F : GL_RGBA32F, size.x, size.y, 0,
                   depth ? GL_DEPTH_COMPONENT : GL_RGBA, GL_FLOAT, nullptr);
    gl_.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    gl_.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    gl_.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    gl_.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  }
  gl_.check("creating the frame plan's targets");
}

void GlTargets::clear(const std::string& name) {
  const TargetSpec& s = spec(name, "clear");
  const bool depth = s.kind == TargetKind::Depth;
  const GlTargetRef fb = depth ? framebuffer({}, name, "clear") : framebuffer({name}, "", "clear");
  gl_.BindFramebuffer(GL_FRAMEBUFFER, fb.framebuffer);
  const GLenum buffer = depth ? GL_NONE : GL_COLOR_ATTACHMENT0;
  gl_.DrawBuffers(1, &buffer);
  if (depth) {
    const float far = 1.0f;
    gl_.DepthMask(GL_TRUE);  // clearing depth obeys the depth mask
    gl_.ClearBufferfv(GL_DEPTH, 0, &far);
  } else {
    gl_.ClearBufferfv(GL_COLOR, 0, &s.clear.x);
  }
}

const TargetSpec& GlTargets::spec(const std::string& name, const std::string& pass) const {
  for (const TargetSpec& s : specs_)
    if (s.name == name) return s;
  throw std::runtime_error("frame plan: pass '" + pass + "' names target '" + name +
                           "', which the plan does not declare");
}

GLuint GlTargets::texture(const std::string& name, const std::string& pass) const {
  spec(name, pass);
  return textures_.at(name);
}

GlTargetRef GlTargets::framebuffer(const std::vector<std::string>& colours,
                                   const std::string& depth, const std::string& pass) {
  std::string key;
  for (const std::string& c : colours) key += c + ",";
  key += "|" + depth;
  const auto found = framebuffers_.find(key);
  if (found != framebuffers_.end()) return found->second;
  GlTargetRef ref;
  const std::string& first = colours.empty() ? depth : colours.front();
  const glm::ivec2 size = first.empty() ? glm::ivec2(width_, height_) : size_of(spec(first, pass));
  for (const std::string& c : colours)
    if (size_of(spec(c, pass)) != size)
      throw std::runtime_error("frame plan: pass '" + pass + "' draws into targets of two sizes");
  if (!depth.empty() && size_of(spec(depth, pass)) != size)
    throw std::runtime_error("frame plan: pass '" + pass + "' draws into targets of two sizes");
  ref.width = size.x;
  ref.height = size.y;
  ref.color_attachments = int(colours.size());
  ref.depth = !depth.empty();
  gl_.GenFramebuffers(1, &ref.framebuffer);
  gl_.BindFramebuffer(GL_FRAMEBUFFER, ref.framebuffer);
  for (size_t i = 0; i < colours.size(); ++i) {
    if (spec(colours[i], pass).kind != TargetKind::Colour)
      throw std::runtime_error("frame plan: pass '" + pass + "' writes colour into depth target '" +
                               colours[i] + "'");
    gl_.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0 + GLenum(i), GL_TEXTURE_2D,
                             texture(colours[i], pass), 0);
  }
  if (ref.depth) {
    if (spec(depth, pass).kind != TargetKind::Depth)
      throw std::runtime_error("frame plan: pass '" + pass + "' uses colour target '" + depth +
                               "' as depth");
    gl_.FramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D,
                             texture(depth, pass), 0);
  }
  framebuffers_[key] = ref;
  if (gl_.CheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
    throw std::runtime_error("frame plan: pass '" + pass + "' has an incomplete framebuffer");
  gl_.check("creating a framebuffer for pass '" + pass + "'");
  return ref;
}

}  // namespace sdfreel
