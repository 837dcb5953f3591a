#pragma once
// The FrameContext as GLSL uniforms (the declarations are in shaders/common/frame.glsl).
#include <vector>

#include "render/frame_context.h"
#include "scenes/scene.h"

namespace sdfreel {

// Longest sample list the shaders accept (SDFREEL_MAX_SAMPLES); the CLI allows up to 1024.
constexpr int MAX_SHADER_SAMPLES = 1024;

// Resolution, frame, TIME, camera basis, pixel angle, march settings, sample offsets and count,
// and every scene parameter as p_<name>. Numbers are computed exactly as the CPU backend does.
std::vector<ShaderUniform> frame_uniforms(const FrameContext& ctx);

}  // namespace sdfreel
