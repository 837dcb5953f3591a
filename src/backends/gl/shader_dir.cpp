#include "backends/gl/shader_dir.h"

#include <cstdlib>
#include <filesystem>
#include <system_error>
#include <vector>

#include "backends/gl/shader_source.h"
#include "render/data_files.h"

namespace sdfreel {

namespace fs = std::filesystem;

namespace {

// A folder counts as the shader folder when it holds the shared GLSL.
bool is_shader_dir(const fs::path& dir) {
  std::error_code ec;
  return fs::is_directory(dir / "common", ec);
}

}  // namespace

std::string find_shader_dir() {
  if (const char* env = std::getenv("SDFREEL_SHADER_DIR"); env && *env) {
    if (!is_shader_dir(env))
      throw ShaderError(std::string("SDFREEL_SHADER_DIR=") + env +
                        " is not a shader folder (it has no common/ subfolder)");
    return env;
  }
  const std::vector<fs::path> candidates = data_file_candidates("shaders");
  std::error_code ec;
  std::string tried;
  for (const fs::path& c : candidates) {
    if (is_shader_dir(c)) return fs::weakly_canonical(c, ec).string();
    tried += (tried.empty() ? "" : ", ") + c.string();
  }
  throw ShaderError("cannot find the GLSL shader folder (tried " + tried +
                    "); set SDFREEL_SHADER_DIR");
}

}  // namespace sdfreel
