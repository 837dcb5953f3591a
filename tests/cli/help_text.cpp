#include "cli/help_text.h"

#include <gtest/gtest.h>

#include <regex>
#include <sstream>

#include "cli/harness.h"

namespace sdfreel::test {

std::vector<std::string> commands() {
  const std::string help = run_sdfreel("--help").out;
  std::vector<std::string> out;
  // CLI11 2.4 heads the list "Subcommands:", 2.6 "SUBCOMMANDS:".
  size_t at = help.find("Subcommands:");
  if (at == std::string::npos) at = help.find("SUBCOMMANDS:");
  EXPECT_NE(at, std::string::npos) << help;
  std::istringstream in(at == std::string::npos ? "" : help.substr(at));
  std::string line;
  std::getline(in, line);
  std::smatch m;
  while (std::getline(in, line))
    if (std::regex_search(line, m, std::regex("^  ([a-z]+) "))) out.push_back(m[1]);
  return out;
}

// Each option of `sdfreel CMD --help` as its spellings: {"-o", "--output"}, {"--frames"}.
std::vector<std::vector<std::string>> options_of(const std::string& cmd) {
  std::vector<std::vector<std::string>> out;
  std::istringstream in(run_sdfreel(cmd + " --help").out);
  std::string line;
  std::smatch m;
  while (std::getline(in, line)) {
    // "  -o,--output TEXT" (CLI11 2.4), or "  -o,     --output TEXT" and
    // "          --frames TEXT" (2.6).
    if (!std::regex_search(line, m, std::regex("^ {2,12}(-[-a-z0-9]+(, *-[-a-z0-9]+)*)"))) continue;
    std::vector<std::string> names;
    std::istringstream parts(m[1].str());
    for (std::string n; std::getline(parts, n, ',');) names.push_back(n.substr(n.find('-')));
    if (names.back() != "--help") out.push_back(names);
  }
  return out;
}

}  // namespace sdfreel::test
