#pragma once
// GLSL source assembly: a tiny #include resolver that keeps the file/line mapping. Mesa has no
// #include, so the driver inlines `#include "path"` lines itself (paths relative to the shader
// folder, each file once) and emits a #line directive around every inlined file. Mesa 22 reports
// the source-string number of #line for syntax errors but 0 for some semantic ones (an undeclared
// name), so the file is encoded in the line number itself: line n of file k is numbered
// k * SHADER_LINE_BLOCK + n, and map_shader_log turns the compiler's "S:LINE(COL): ..." back into
// FILE:LINE:COL whatever S says.
#include <stdexcept>
#include <string>
#include <vector>

namespace sdfreel {

// A shader that cannot be read, compiled or linked; what() names FILE:LINE where known.
struct ShaderError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

constexpr int SHADER_LINE_BLOCK = 100000;  // lines per file, at most

struct ShaderSource {
  std::string text;                // for glShaderSource
  std::vector<std::string> files;  // source-string number -> path (as given, under the folder)
};

// Reads `file` under `dir`, inlines its includes and puts `preamble` (the #version line and any
// #defines, owned by the driver: shader files must not contain #version) in front.
ShaderSource load_shader_source(const std::string& dir, const std::string& file,
                                const std::string& preamble);

// Rewrites the compiler's "S:LINE(COL): msg" lines as "DIR/FILE:LINE:COL: msg"; other lines are
// kept. `dir` is prefixed so the message points at a file one can open.
std::string map_shader_log(const std::string& log, const ShaderSource& source,
                           const std::string& dir);

}  // namespace sdfreel
