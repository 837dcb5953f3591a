#pragma once
// The fragment shader sdfreel compiles for one Shadertoy pass: a wrapper that declares
// Shadertoy's uniforms and sdfreel's camera, the Common tab and the pass verbatim (each after a
// #line with its own source number), and a main() that calls mainImage. Compile logs are mapped
// back to the user's files, the wrapper's lines not counted.
#include <string>

#include "shader/shader_project.h"
#include "timeline/timeline.h"

namespace sdfreel {

std::string shadertoy_fragment_source(const ShaderProject& project, const ShaderPass& pass);

// An InputError at the first error the log names, in the user's file, line and column; the whole
// log, its locations rewritten to FILE:LINE:COLUMN, as the message.
InputError shadertoy_compile_error(const ShaderProject& project, const ShaderPass& pass,
                                   const std::string& log);

}  // namespace sdfreel
