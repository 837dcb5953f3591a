#pragma once
// The named targets of a frame plan on GL: one texture each (RGBA32F, or DEPTH_COMPONENT32F for
// depth targets, so later passes can sample depth), frame-sized unless the spec gives a size, and
// framebuffers combining them as passes write them (all of a framebuffer's targets one size). Kept
// from frame to frame while the size and the list of targets stay the same.
#include <map>
#include <string>
#include <vector>

#include "backends/gl/gl_api.h"
#include "backends/gl/gl_platform.h"
#include "render/frame_plan.h"

namespace sdfreel {

class GlTargets {
 public:
  explicit GlTargets(const GlApi& gl) : gl_(gl) {}
  ~GlTargets() { release(); }
  GlTargets(const GlTargets&) = delete;
  GlTargets& operator=(const GlTargets&) = delete;

  // (Re)allocates when size or specs differ from the last call; otherwise keeps everything.
  void prepare(const std::vector<TargetSpec>& specs, int width, int height);
  // Fills the target with its clear value (depth targets: 1).
  void clear(const std::string& name);
  GLuint texture(const std::string& name, const std::string& pass) const;
  const TargetSpec& spec(const std::string& name, const std::string& pass) const;
  // A framebuffer writing `colours` (fragment outputs 0..n-1) and `depth` ("" = none).
  GlTargetRef framebuffer(const std::vector<std::string>& colours, const std::string& depth,
                          const std::string& pass);

 private:
  void release();
  const GlApi& gl_;
  int width_ = 0, height_ = 0;
  std::vector<TargetSpec> specs_;
  glm::ivec2 size_of(const TargetSpec& s) const;
  std::map<std::string, GLuint> textures_;
  std::map<std::string, GlTargetRef> framebuffers_;  // by "colour,colour|depth"
};

}  // namespace sdfreel
