#pragma once
// The uniforms sdfreel declares for every pass of a user's shader (docs/shaders.md): Shadertoy's
// and the timeline camera's, with their GLSL declarations. One table: the GL wrapper declares
// them from it, the runner sets them by name, and a shader that declares one again is refused.
#include <string>
#include <vector>

namespace sdfreel {

struct ShadertoyUniform {
  const char* type;  // GLSL type, with [4] after the name for arrays (`array`)
  const char* name;
  bool array = false;
};

const std::vector<ShadertoyUniform>& shadertoy_uniforms();

// Whether `name` is one of them.
bool is_shadertoy_uniform(const std::string& name);

}  // namespace sdfreel
