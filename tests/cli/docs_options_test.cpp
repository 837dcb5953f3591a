// docs/cli.md against the CLI itself: every command of `sdfreel --help` is in the page's command
// table, every option of its `--help` is in its section or in the shared options table, and every
// option the page names exists (other programs' options listed below).
#include <gtest/gtest.h>

#include <map>
#include <regex>
#include <set>
#include <sstream>

#include "cli/harness.h"
#include "cli/help_text.h"

namespace sdfreel::test {
namespace {

const std::string kPage = std::string(SDFREEL_SOURCE_DIR) + "/docs/cli.md";

// CLI11's own (every command has them) and sbatch's, in the page's Slurm commands.
const std::set<std::string> kOtherOptions = {"--help", "--version", "--parsable", "--dependency"};

// `name` as a word of `text`: after a backtick or a space, not followed by more of a name.
bool mentions(const std::string& text, const std::string& name) {
  return std::regex_search(text, std::regex("(^|[` ])" + name + "($|[^a-z0-9-])"));
}

// The page's "## " sections by heading.
std::map<std::string, std::string> sections(const std::string& page) {
  std::map<std::string, std::string> out;
  std::string heading;
  std::istringstream in(page);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("## ", 0) == 0) heading = line.substr(3);
    out[heading] += line + "\n";
  }
  return out;
}

TEST(DocsOptions, EveryCommandAndOptionOfTheCliIsOnThePage) {
  const std::string page = read_file(kPage);
  ASSERT_FALSE(page.empty()) << kPage;
  const auto by_heading = sections(page);
  std::string shared;
  for (const auto& [heading, text] : by_heading)
    if (heading.rfind("Options of", 0) == 0) shared += text;
  const std::vector<std::string> cmds = commands();
  ASSERT_GE(cmds.size(), 10u);
  for (const std::string& cmd : cmds) {
    EXPECT_NE(page.find("| `sdfreel " + cmd), std::string::npos) << cmd << " is not in the table";
    std::string text = shared;
    for (const auto& [heading, t] : by_heading)
      if (heading.rfind("`" + cmd + "`", 0) == 0) text += t;
    for (const auto& names : options_of(cmd)) {
      bool found = false;
      for (const std::string& n : names) found |= mentions(text, n);
      EXPECT_TRUE(found) << cmd << " " << names.back() << " is not in docs/cli.md (its section "
                         << "or the options table)";
    }
  }
}

TEST(DocsOptions, EveryOptionOnThePageExists) {
  std::set<std::string> known = kOtherOptions;
  for (const std::string& cmd : commands())
    for (const auto& names : options_of(cmd)) known.insert(names.begin(), names.end());
  const std::string page = read_file(kPage);
  const std::regex option("--[a-z][a-z0-9-]*");
  for (auto it = std::sregex_iterator(page.begin(), page.end(), option);
       it != std::sregex_iterator(); ++it)
    EXPECT_TRUE(known.count(it->str())) << it->str() << " is on docs/cli.md but no command has it";
}

}  // namespace
}  // namespace sdfreel::test
