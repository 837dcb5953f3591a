#pragma once
// Numbers and textures the CPU side computes once per frame and hands to a pass's GLSL program
// (OSMesa backend), so both backends start from identical inputs.
#include <string>
#include <vector>

namespace sdfreel {

// A per-frame constant: the same number prepare() computed for the C++ path.
struct ShaderUniform {
  std::string name;           // GLSL uniform name
  int components = 1;         // 1..4: float, vec2, vec3, vec4; 16: mat4 (column-major)
  std::vector<float> values;  // components * array length (array when longer)
};

// A texture a scene generates (blue noise, sky, paper maps) for its GLSL twin. Shaders should
// read it with texelFetch and filter in code exactly as the C++ path does.
struct ShaderTexture {
  std::string name;  // sampler uniform name
  int width = 0, height = 0, channels = 4;
  std::vector<float> texels;  // width * height * channels, row-major, row 0 first
};

}  // namespace sdfreel
