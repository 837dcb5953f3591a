#pragma once
// Where the GLSL files live at run time.
#include <string>

namespace sdfreel {

// The shader folder: env SDFREEL_SHADER_DIR if set (it must exist), else the first folder holding
// common/ of data_file_candidates("shaders") (render/data_files.h: <prefix>/share/sdfreel/shaders,
// or the source tree's from a build tree). Throws ShaderError when none is found.
std::string find_shader_dir();

}  // namespace sdfreel
