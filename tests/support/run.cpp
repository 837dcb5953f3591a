#include "support/run.h"

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>

#include "support/scratch.h"

namespace sdfreel::test {

namespace fs = std::filesystem;

RunResult run(const std::string& command, const std::string& cwd, const std::string& env) {
  const fs::path dir = fs::temp_directory_path() / "sdfreel-test-io";
  fs::create_directories(dir);
  static int counter = 0;
  const std::string id = std::to_string(::getpid()) + "-" + std::to_string(counter++);
  const std::string out = (dir / ("out-" + id)).string(), err = (dir / ("err-" + id)).string();
  // Braces: the whole command (even one with `&` or `;`) runs in `cwd` with both streams captured.
  const std::string full =
      "cd '" + cwd + "' && { " + env + command + "\n} >'" + out + "' 2>'" + err + "'";
  const int raw = std::system(full.c_str());
  RunResult r;
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  r.out = read_file(out);
  r.err = read_file(err);
  fs::remove(out);
  fs::remove(err);
  return r;
}

std::string sdfreel_binary() {
  const char* other = std::getenv("SDFREEL_TEST_BINARY");
  return other && *other ? other : SDFREEL_BINARY;
}

RunResult run_sdfreel(const std::string& args, const std::string& cwd, const std::string& env) {
  return run("'" + sdfreel_binary() + "' " + args, cwd, env);
}

bool have_tool(const std::string& name) {
  return std::system(("command -v " + name + " >/dev/null 2>&1").c_str()) == 0;
}

}  // namespace sdfreel::test
