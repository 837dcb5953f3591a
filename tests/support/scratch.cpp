#include "support/scratch.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace sdfreel::test {

namespace fs = std::filesystem;

std::string scratch_dir(const std::string& name) {
  // ctest runs test_gl once per GL platform, possibly at the same time: each gets its own folders.
  const char* platform = std::getenv("SDFREEL_GL_PLATFORM");
  const std::string suffix = platform && *platform ? std::string("-") + platform : "";
  const fs::path p = fs::temp_directory_path() / ("sdfreel-test-" + name + suffix);
  fs::remove_all(p);
  fs::create_directories(p);
  return p.string();
}

void write_file(const std::string& path, const std::string& text) {
  std::ofstream f(path, std::ios::binary);
  f << text;
}

std::string read_file(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  std::stringstream ss;
  ss << f.rdbuf();
  return ss.str();
}

std::string source_path(const std::string& rel) {
  return std::string(SDFREEL_SOURCE_DIR) + "/" + rel;
}

}  // namespace sdfreel::test
