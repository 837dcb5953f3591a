#pragma once
// Shadertoy's JSON export of a shader read as a ShaderProject (docs/shaders.md). Both forms in
// circulation: the public API's ({"Shader": {"renderpass": [...]}}, inputs with `ctype`, `src`,
// `channel`, `sampler`) and the site's own export (a list of shaders, inputs with `type`,
// `filepath`). Buffer inputs name the buffer by its output id; a texture's file is looked up by
// its file name beside the JSON, then in each of `texture_dirs`; a cubemap's six faces are
// NAME.EXT, NAME_1.EXT .. NAME_5.EXT.
#include <string>
#include <vector>

#include "shader/shader_project.h"

namespace sdfreel {

// `text`: the file's bytes; `path` names it in messages. Throws InputError (file, line, column
// where known) on anything that is not such an export or uses what sdfreel does not support
// (keyboard, video, webcam, music, the Sound tab), saying so.
ShaderProject read_shadertoy_json(const std::string& path, const std::string& text,
                                  const std::vector<std::string>& texture_dirs);

}  // namespace sdfreel
