#pragma once
// The CLI as `sdfreel --help` describes it, read back for the tests that hold other texts to it
// (docs/cli.md, the man page, the bash completion).
#include <string>
#include <vector>

namespace sdfreel::test {

// The commands `sdfreel --help` lists, in its order.
std::vector<std::string> commands();

// Each option of `sdfreel CMD --help` as its spellings: {"-o", "--output"}, {"--frames"}.
std::vector<std::vector<std::string>> options_of(const std::string& cmd);

}  // namespace sdfreel::test
