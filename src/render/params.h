#pragma once
// Scene parameters: their declarations (ParamSpec) and the values resolved for one frame.
#include <glm/glm.hpp>
#include <string>
#include <vector>

namespace sdfreel {

struct ParamSpec {
  std::string name;
  int components = 1;           // 1 = scalar, 3 = vector/colour
  std::vector<double> def;      // default, `components` values
  double min = 0.0, max = 1.0;  // inclusive range, applies to each component
  std::string doc;              // one line: meaning and unit
};

// Values for one frame, in the order of the scene's ParamSpec list.
class ParamValues {
 public:
  ParamValues() = default;
  explicit ParamValues(const std::vector<ParamSpec>* specs);  // filled with defaults
  void set(const std::string& name, const std::vector<double>& v);
  double scalar(const std::string& name) const;
  glm::vec3 vec3(const std::string& name) const;
  const std::vector<double>& raw(const std::string& name) const;
  const std::vector<ParamSpec>& specs() const { return *specs_; }
  const std::vector<std::vector<double>>& values() const { return values_; }

 private:
  int index_of(const std::string& name) const;  // throws std::out_of_range on unknown names
  const std::vector<ParamSpec>* specs_ = nullptr;
  std::vector<std::vector<double>> values_;
};

const ParamSpec* find_param(const std::vector<ParamSpec>& specs, const std::string& name);

}  // namespace sdfreel
