#include "shader/glsl_text.h"

#include <algorithm>
#include <cstdlib>
#include <regex>

namespace sdfreel {

std::string without_comments(const std::string& s) {
  std::string out = s;
  for (size_t i = 0; i + 1 < out.size(); ++i) {
    if (out[i] == '/' && out[i + 1] == '/') {
      for (; i < out.size() && out[i] != '\n'; ++i) out[i] = ' ';
    } else if (out[i] == '/' && out[i + 1] == '*') {
      size_t j = i;
      for (; j < out.size() && !(out[j] == '*' && j + 1 < out.size() && out[j + 1] == '/'); ++j)
        if (out[j] != '\n') out[j] = ' ';
      for (size_t k = j; k < std::min(out.size(), j + 2); ++k) out[k] = ' ';
      i = j + 1;
    }
  }
  return out;
}

bool declares_function(const std::string& glsl, const std::string& name) {
  const std::regex re("\\bvoid\\s+" + name + "\\s*\\(");
  return std::regex_search(without_comments(glsl), re);
}

std::vector<DeclaredUniform> declared_uniforms(const std::string& glsl) {
  const std::string text = without_comments(glsl);
  static const std::regex re(
      "\\buniform\\s+(?:(?:highp|mediump|lowp)\\s+)?(float|vec2|vec3|vec4)\\s+([A-Za-z_]\\w*)"
      "\\s*(?:=\\s*([^;]*))?;");
  static const std::regex number("[-+]?(?:\\d+\\.?\\d*|\\.\\d+)(?:[eE][-+]?\\d+)?");
  std::vector<DeclaredUniform> out;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), re); it != std::sregex_iterator();
       ++it) {
    const std::smatch& m = *it;
    DeclaredUniform u;
    const std::string type = m[1];
    u.components = type == "float" ? 1 : type[3] - '0';
    u.name = m[2];
    u.line = 1 + int(std::count(text.begin(), text.begin() + m.position(0), '\n'));
    if (m[3].matched) {
      static const std::regex constructor("\\b(?:float|vec[234])\\s*\\(");
      const std::string init = std::regex_replace(m[3].str(), constructor, " ");  // not vec3's 3
      std::vector<double> values;
      for (auto n = std::sregex_iterator(init.begin(), init.end(), number);
           n != std::sregex_iterator(); ++n)
        values.push_back(std::strtod(n->str().c_str(), nullptr));
      // vecN(x) fills every component with x, as GLSL does.
      if (values.size() == 1) values.assign(size_t(u.components), values[0]);
      if (int(values.size()) == u.components) u.init = values;
    }
    out.push_back(std::move(u));
  }
  return out;
}

}  // namespace sdfreel
