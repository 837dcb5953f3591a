#pragma once
// What sdfreel reads from a user's GLSL without compiling it: functions it defines and uniforms
// it declares (its timeline parameters). Comments are skipped; the preprocessor is not run.
#include <string>
#include <vector>

namespace sdfreel {

// The text with // and /* */ comments replaced by spaces (newlines kept, so lines still count).
std::string without_comments(const std::string& glsl);

// True when `glsl` defines `void NAME(`.
bool declares_function(const std::string& glsl, const std::string& name);

struct DeclaredUniform {
  std::string name;
  int components = 1;        // float 1, vec2 2, vec3 3, vec4 4
  std::vector<double> init;  // the initialiser's numbers when it is a literal, else empty
  int line = 0;              // 1-based line of the declaration
};

// `uniform float|vec2|vec3|vec4 NAME [= literal];` declarations, in file order.
std::vector<DeclaredUniform> declared_uniforms(const std::string& glsl);

}  // namespace sdfreel
