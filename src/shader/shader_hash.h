#pragma once
// The SHA-256 of everything a user's shader is made of (its code, bindings and texture bytes), in
// the manifest beside the build's versions: frames of a changed shader no longer match on resume.
#include <string>

#include "shader/shader_project.h"

namespace sdfreel {

std::string shader_project_sha256(const ShaderProject& project);

}  // namespace sdfreel
