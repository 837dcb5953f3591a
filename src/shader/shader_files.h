#pragma once
// Reading a user's shader from disk: a folder of Shadertoy tabs (image.glsl, buffer_a.glsl ..
// buffer_d.glsl, cube_a.glsl, common.glsl, and channels.toml for the bindings), one .glsl file
// (an Image-only shader) or Shadertoy's JSON export (shadertoy_json.h).
#include <string>
#include <vector>

#include "shader/shader_project.h"

namespace sdfreel {

// Throws InputError naming the file and what to fix. `texture_dirs`: where a JSON input's file
// is looked for after the JSON's own folder.
ShaderProject read_shader_files(const std::string& path,
                                const std::vector<std::string>& texture_dirs);

// A text file of at most 4 MiB; InputError naming `path` otherwise.
std::string read_shader_text(const std::string& path);

// A file's bytes, any size (a texture's, for the shader's hash); InputError when unreadable.
std::string read_shader_bytes(const std::string& path);

// Everything that can be checked before a frame: each pass's entry point, reads of passes that do
// not exist, texture files that are missing. Throws InputError.
void check_shader_project(const ShaderProject& project);

}  // namespace sdfreel
