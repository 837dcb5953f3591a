#include "cli/harness.h"

#include <sys/wait.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace sdfreel::test {

namespace fs = std::filesystem;

RunResult run(const std::string& command, const std::string& cwd) {
  const fs::path dir = fs::temp_directory_path() / "sdfreel-test-io";
  fs::create_directories(dir);
  static int counter = 0;
  const std::string id = std::to_string(::getpid()) + "-" + std::to_string(counter++);
  const std::string out = (dir / ("out-" + id)).string(), err = (dir / ("err-" + id)).string();
  // Braces: the whole command (even one with `&` or `;`) runs in `cwd` with both streams captured.
  const std::string full =
      "cd '" + cwd + "' && { " + command + "\n} >'" + out + "' 2>'" + err + "'";
  const int raw = std::system(full.c_str());
  RunResult r;
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  r.out = read_file(out);
  r.err = read_file(err);
  fs::remove(out);
  fs::remove(err);
  return r;
}

RunResult sdfreel(const std::string& args, const std::string& cwd) {
  return run(std::string("'") + SDFREEL_BINARY + "' " + args, cwd);
}

bool have_tool(const std::string& name) {
  return std::system(("command -v " + name + " >/dev/null 2>&1").c_str()) == 0;
}

std::string make_scratch_dir(const std::string& name) {
  const fs::path p = fs::temp_directory_path() / ("sdfreel-test-" + name);
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

std::vector<std::string> framemd5_data_lines(const std::string& text) {
  std::vector<std::string> lines;
  std::stringstream ss(text);
  std::string line;
  while (std::getline(ss, line))
    if (!line.empty() && line[0] != '#') lines.push_back(line);
  return lines;
}

std::string source_path(const std::string& rel) {
  return std::string(SDFREEL_SOURCE_DIR) + "/" + rel;
}

std::string small_timeline(int frames, const std::string& codec, const std::string& video,
                           const std::string& extra) {
  char duration[32];
  std::snprintf(duration, sizeof duration, "%.6f", frames / 10.0);
  return std::string("[video]\nscene = \"sdf_morph\"\nfps = 10\nduration = ") + duration +
         "\nresolution = [64, 36]\nsamples = 1\nquality = \"draft\"\n\n[output]\ndir = \"out\"\n"
         "frames = [\"exr\", \"png\"]\nvideo = \"" +
         video + "\"\ncodec = \"" + codec + "\"\n\n" +
         "[camera]\nkeys = [\n  { t = 0.0, position = [0.0, 1.5, -4.0], target = [0.0, 0.6, 0.0], "
         "fov = 40.0 },\n  { t = 2.0, position = [3.0, 1.8, -2.5], target = [0.0, 0.7, 0.0], fov = "
         "45.0 },\n]\n\n[params]\nmorph_period = 2.0\n" +
         extra;
}

}  // namespace sdfreel::test
