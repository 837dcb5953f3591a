#pragma once
// The one way to build a list of GLSL uniforms (the frame's, a scene's shader_uniforms()): names
// under an optional struct prefix ("u_lake" + "amp" -> "u_lake.amp"), values as floats (ints and
// flags too: the OSMesa driver converts them).
#include <glm/glm.hpp>
#include <string>
#include <utility>
#include <vector>

#include "scenes/scene.h"

namespace sdfreel {

class UniformList {
 public:
  explicit UniformList(std::string prefix = "") : prefix_(std::move(prefix)) {}
  UniformList& f(const std::string& name, float v) { return add(name, 1, {v}); }
  UniformList& flag(const std::string& name, bool v) { return f(name, v ? 1.0f : 0.0f); }
  UniformList& v2(const std::string& name, const glm::vec2& v) { return add(name, 2, {v.x, v.y}); }
  UniformList& v3(const std::string& name, const glm::vec3& v) {
    return add(name, 3, {v.x, v.y, v.z});
  }
  // An array (or a vector of `components`): values.size() = components * length.
  UniformList& add(const std::string& name, int components, std::vector<float> values) {
    out_.push_back(ShaderUniform{prefix_.empty() ? name : prefix_ + "." + name, components,
                                 std::move(values)});
    return *this;
  }
  void append_to(std::vector<ShaderUniform>& all) const {
    all.insert(all.end(), out_.begin(), out_.end());
  }
  const std::vector<ShaderUniform>& uniforms() const { return out_; }

 private:
  std::string prefix_;
  std::vector<ShaderUniform> out_;
};

}  // namespace sdfreel
