#pragma once

namespace sdfreel {

// Parses the command line and runs one command. Returns the process exit status:
// 0 success, 1 render/encode/verification failure, 2 bad usage or bad input.
int run_cli(int argc, char** argv);

}  // namespace sdfreel
