#pragma once
// Where the GLSL files live at run time.
#include <string>

namespace sdfreel {

// The shader folder: env SDFREEL_SHADER_DIR if set (it must exist), else the first of ../shaders,
// ../../shaders and ../share/sdfreel/shaders next to the executable (/proc/self/exe) that holds
// common/, else the source tree's shaders/ (compile-time SDFREEL_SOURCE_DIR). Throws ShaderError
// when none is found.
std::string find_shader_dir();

}  // namespace sdfreel
