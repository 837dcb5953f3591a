#include "osmesa/run_binary.h"

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace sdfreel::test {

namespace fs = std::filesystem;

BinaryResult run_sdfreel(const std::string& args, const std::string& env) {
  static int counter = 0;
  const fs::path dir =
      fs::temp_directory_path() / ("sdfreel-osmesa-run-" + std::to_string(getpid()));
  fs::create_directories(dir);
  const std::string id = std::to_string(counter++);
  const std::string out = (dir / ("out-" + id)).string(), err = (dir / ("err-" + id)).string();
  const std::string cmd =
      env + "'" + SDFREEL_BINARY + "' " + args + " >'" + out + "' 2>'" + err + "'";
  const int raw = std::system(cmd.c_str());
  BinaryResult r;
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  r.out = read_text(out);
  r.err = read_text(err);
  fs::remove_all(dir);
  return r;
}

std::string scratch_dir(const std::string& name) {
  const fs::path p = fs::temp_directory_path() / ("sdfreel-osmesa-" + name);
  fs::remove_all(p);
  fs::create_directories(p);
  return p.string();
}

void write_text(const std::string& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

std::string read_text(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  std::stringstream ss;
  ss << f.rdbuf();
  return ss.str();
}

}  // namespace sdfreel::test
