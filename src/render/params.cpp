#include "render/params.h"

#include <stdexcept>

namespace sdfreel {

ParamValues::ParamValues(const std::vector<ParamSpec>* specs) : specs_(specs) {
  for (const ParamSpec& s : *specs) values_.push_back(s.def);
}

int ParamValues::index_of(const std::string& name) const {
  if (specs_)
    for (size_t i = 0; i < specs_->size(); ++i)
      if ((*specs_)[i].name == name) return int(i);
  throw std::out_of_range("unknown scene parameter '" + name + "'");
}

void ParamValues::set(const std::string& name, const std::vector<double>& v) {
  values_[index_of(name)] = v;
}

double ParamValues::scalar(const std::string& name) const {
  return values_[index_of(name)].at(0);
}

glm::vec3 ParamValues::vec3(const std::string& name) const {
  const std::vector<double>& v = values_[index_of(name)];
  if (v.size() == 1) return glm::vec3(float(v[0]));
  return glm::vec3(float(v.at(0)), float(v.at(1)), float(v.at(2)));
}

const std::vector<double>& ParamValues::raw(const std::string& name) const {
  return values_[index_of(name)];
}

const ParamSpec* find_param(const std::vector<ParamSpec>& specs, const std::string& name) {
  for (const ParamSpec& s : specs)
    if (s.name == name) return &s;
  return nullptr;
}

}  // namespace sdfreel
