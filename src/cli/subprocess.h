#pragma once
// Runs a program (found on PATH) without a shell and captures its standard output.
#include <string>
#include <vector>

namespace sdfreel {

struct ProgramResult {
  int status = -1;  // exit status; 127 when it could not be started, 128+N when killed by signal N
  std::string out;  // stdout; stderr goes to ours
};

ProgramResult run_program(const std::vector<std::string>& argv);
// True when `name` is an executable file in a folder of PATH.
bool on_path(const std::string& name);

}  // namespace sdfreel
