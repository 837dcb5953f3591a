#pragma once
// A user's shader as the rest of sdfreel sees a scene: its timeline parameters are the uniforms it
// declares (plus Shadertoy's iMouse), it has no C++ twin (the GL backend runs it), and its output
// is display-referred unless [shader] output = "linear".
#include <memory>

#include "scenes/scene.h"
#include "shader/shader_project.h"

namespace sdfreel {

// Throws InputError when two tabs declare one uniform with different types, or a uniform's name
// is one of the uniforms sdfreel itself declares.
std::shared_ptr<const SceneInfo> make_shader_scene(std::shared_ptr<const ShaderProject> project,
                                                   const std::string& name);

}  // namespace sdfreel
