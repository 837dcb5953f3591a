#pragma once
// Runs the built sdfreel binary in a subprocess (with extra environment variables) for the
// end-to-end tests of the osmesa backend.
#include <string>

namespace sdfreel::test {

struct BinaryResult {
  int status = -1;
  std::string out, err;
};

// `env` is prefixed to the command, e.g. "LP_NUM_THREADS=1 ".
BinaryResult run_sdfreel(const std::string& args, const std::string& env = "");
std::string scratch_dir(const std::string& name);  // fresh and empty, under the temp folder
void write_text(const std::string& path, const std::string& text);
std::string read_text(const std::string& path);

}  // namespace sdfreel::test
