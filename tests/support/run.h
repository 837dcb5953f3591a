#pragma once
// Runs commands, and the sdfreel binary this build made, for end-to-end tests.
#include <string>

namespace sdfreel::test {

struct RunResult {
  int status = -1;  // exit status; -1 when the command did not exit normally
  std::string out, err;
};

// `command` through /bin/sh in `cwd` with `env` prefixed (e.g. "LP_NUM_THREADS=1 "), capturing
// stdout and stderr.
RunResult run(const std::string& command, const std::string& cwd = ".",
              const std::string& env = "");
// The sdfreel under test: $SDFREEL_TEST_BINARY when set (to run the end-to-end tests against
// another build, e.g. to see them fail on one without a fix), else the binary of this build.
std::string sdfreel_binary();
// `sdfreel ARGS`.
RunResult run_sdfreel(const std::string& args, const std::string& cwd = ".",
                      const std::string& env = "");
bool have_tool(const std::string& name);  // on PATH

}  // namespace sdfreel::test
