// No broken link between the README and the pages under docs/: every relative link or picture of
// a Markdown file (Markdown's `](target)` or HTML's `href="target"` and `src="target"`, as the
// README's gallery uses) names a file that exists, and every #anchor a heading of the page it
// points to (GitHub's slugs: lower case, spaces to '-', other punctuation dropped). Links to the
// web are not followed.
#include <gtest/gtest.h>

#include <cctype>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace sdfreel::testing {
namespace {

namespace fs = std::filesystem;

std::string read_text(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// GitHub's anchor for a heading's text.
std::string slug(const std::string& heading) {
  std::string s;
  for (const char c : heading) {
    if (std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_')
      s += char(std::tolower(static_cast<unsigned char>(c)));
    else if (c == ' ')
      s += '-';
  }
  return s;
}

// The anchors of a Markdown file's headings (outside fenced code).
std::set<std::string> anchors(const std::string& markdown) {
  std::set<std::string> out;
  std::istringstream in(markdown);
  std::string line;
  bool fenced = false;
  while (std::getline(in, line)) {
    if (line.rfind("```", 0) == 0) fenced = !fenced;
    if (fenced || line.empty() || line[0] != '#') continue;
    const size_t text = line.find_first_not_of('#');
    if (text != std::string::npos && line[text] == ' ') out.insert(slug(line.substr(text + 1)));
  }
  return out;
}

std::vector<fs::path> markdown_files() {
  const fs::path root(SDFREEL_SOURCE_DIR);
  std::vector<fs::path> files{root / "README.md"};
  for (const auto& e : fs::recursive_directory_iterator(root / "docs"))
    if (e.path().extension() == ".md") files.push_back(e.path());
  return files;
}

TEST(DocsLinks, EveryRelativeLinkAndAnchorResolves) {
  const std::string markdown_link = R"(\]\(([^)\s]+)\))";
  const std::string html_link = "(?:href|src)=\"([^\"]+)\"";
  const std::regex link(markdown_link + "|" + html_link);
  int checked = 0;
  for (const fs::path& file : markdown_files()) {
    const std::string text = read_text(file);
    for (auto it = std::sregex_iterator(text.begin(), text.end(), link);
         it != std::sregex_iterator(); ++it) {
      const std::string target = (*it)[1].matched ? (*it)[1].str() : (*it)[2].str();
      if (target.find("://") != std::string::npos || target.rfind("mailto:", 0) == 0) continue;
      const size_t hash = target.find('#');
      const std::string path = target.substr(0, hash);
      const fs::path resolved = path.empty() ? file : file.parent_path() / path;
      ++checked;
      if (!fs::exists(resolved)) {
        ADD_FAILURE() << file.filename() << " links to " << target << ", which does not exist";
        continue;
      }
      if (hash == std::string::npos || resolved.extension() != ".md") continue;
      const std::string anchor = target.substr(hash + 1);
      EXPECT_TRUE(anchors(read_text(resolved)).count(anchor))
          << file.filename() << " links to " << target << ": no heading of " << resolved.filename()
          << " has the anchor #" << anchor;
    }
  }
  EXPECT_GT(checked, 150);  // the README and the index alone link to dozens of pages and pictures
}

}  // namespace
}  // namespace sdfreel::testing
