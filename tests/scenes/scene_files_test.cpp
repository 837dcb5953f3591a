// Every registered scene brings the files that make it a finished scene, found by name, so that a
// scene registered without them fails here instead of being silently unchecked (the rules are in
// docs/adding-a-scene.md): its code and GLSL in their folders, a timeline in timelines/, a golden,
// a hard case, a picture under docs/, a row in the README's scene table and a page under
// docs/scenes/ whose reference (camera, passes, parameters) is the code's. And every scene folder
// belongs to a registered scene (a misspelt folder would otherwise be skipped).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "scenes/registry.h"
#include "scenes/scene_reference.h"

namespace sdfreel {
namespace {

namespace fs = std::filesystem;

fs::path source(const std::string& rel) {
  return fs::path(SDFREEL_SOURCE_DIR) / rel;
}

std::string read(const fs::path& p) {
  std::ifstream f(p, std::ios::binary);
  std::stringstream ss;
  ss << f.rdbuf();
  return ss.str();
}

// A timeline names its scene on a line `scene = "<name>"` of its [video] table.
bool names_scene(const fs::path& toml, const std::string& scene) {
  const std::regex line("(^|\n)[ \t]*scene[ \t]*=[ \t]*\"" + scene + "\"");
  return std::regex_search(read(toml), line);
}

// The .toml files directly in `dir` (none when it does not exist).
std::vector<fs::path> tomls_in(const fs::path& dir) {
  std::vector<fs::path> out;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(dir, ec))
    if (e.path().extension() == ".toml") out.push_back(e.path());
  return out;
}

bool is_png(const fs::path& p) {
  return read(p).compare(0, 8, "\x89PNG\r\n\x1a\n") == 0;
}

class SceneFiles : public ::testing::TestWithParam<std::string> {
 protected:
  const SceneInfo& info() const { return *find_scene(GetParam()); }
};

TEST_P(SceneFiles, CodeAndShaderInTheSceneFolders) {
  const std::string s = GetParam();
  EXPECT_TRUE(fs::exists(source("src/scenes/" + s + "/" + s + ".cpp")))
      << "the SceneInfo of " << s << " belongs in src/scenes/" << s << "/" << s << ".cpp";
  if (info().shader.empty()) return;  // a CPU-only scene
  EXPECT_EQ(info().shader.rfind(s + "/", 0), 0u)
      << "SceneInfo.shader is relative to shaders/ and starts with " << s << "/";
  EXPECT_TRUE(fs::exists(source("shaders/" + info().shader))) << "shaders/" << info().shader;
}

TEST_P(SceneFiles, HasATimeline) {
  const std::string s = GetParam();
  const fs::path t = source("timelines/" + s + ".toml");
  ASSERT_TRUE(fs::exists(t)) << "missing timelines/" << s << ".toml (the scene's default timeline)";
  EXPECT_TRUE(names_scene(t, s)) << t << " does not render scene " << s;
}

TEST_P(SceneFiles, HasAGolden) {
  const std::string s = GetParam();
  const std::vector<fs::path> goldens = tomls_in(source("tests/golden/" + s));
  EXPECT_FALSE(goldens.empty()) << "missing tests/golden/" << s << "/<name>.toml with its "
                                << "<name>.framemd5 (scripts/regen-golden.sh writes the hashes)";
  for (const fs::path& g : goldens) {
    EXPECT_TRUE(names_scene(g, s)) << g << " does not render scene " << s;
    fs::path hashes = g;
    EXPECT_TRUE(fs::exists(hashes.replace_extension(".framemd5")))
        << "missing " << hashes << "; run scripts/regen-golden.sh and look at the frames";
  }
}

TEST_P(SceneFiles, HasAHardCase) {
  const std::string s = GetParam();
  const std::vector<fs::path> cases = tomls_in(source("tests/hard_cases/" + s));
  EXPECT_FALSE(cases.empty()) << "missing tests/hard_cases/" << s
                              << "/<case>.toml (a timeline aimed at one failure of the march)";
  for (const fs::path& c : cases) EXPECT_TRUE(names_scene(c, s)) << c << " is not of " << s;
}

TEST_P(SceneFiles, HasAPictureInDocs) {
  const std::string s = GetParam();
  const fs::path png = source("docs/" + s + ".png");
  ASSERT_TRUE(fs::exists(png)) << "missing docs/" << s << ".png (a frame of its timeline)";
  EXPECT_TRUE(is_png(png)) << png << " is not a PNG";
}

TEST_P(SceneFiles, HasARowInTheReadmeSceneTable) {
  const std::string s = GetParam();
  const std::regex row("(^|\n)\\| `" + s + "` \\|");
  EXPECT_TRUE(std::regex_search(read(source("README.md")), row))
      << "README.md's scene table has no row starting with | `" << s << "` |";
}

// The page's generated block is what `sdfreel scenes NAME --markdown` prints today: a parameter
// added, renamed or given a new default or range fails here until the page is regenerated.
TEST_P(SceneFiles, HasAPageWhoseReferenceIsTheCodes) {
  const std::string s = GetParam();
  const fs::path page = source("docs/scenes/" + s + ".md");
  ASSERT_TRUE(fs::exists(page)) << "missing docs/scenes/" << s << ".md (docs/adding-a-scene.md)";
  EXPECT_NE(read(page).find(scene_reference_markdown(*find_scene(s))), std::string::npos)
      << page << "'s reference block differs from `sdfreel scenes " << s
      << " --markdown`; run scripts/update-scene-pages.sh";
}

std::vector<std::string> scene_names() {
  std::vector<std::string> names;
  for (const SceneInfo& s : all_scenes()) names.push_back(s.name);
  return names;
}

INSTANTIATE_TEST_SUITE_P(Registered, SceneFiles, ::testing::ValuesIn(scene_names()),
                         [](const ::testing::TestParamInfo<std::string>& i) { return i.param; });

// Folders named after no registered scene (besides the shared common/, and the goldens of the
// example shaders) hold files no test reads.
TEST(SceneFolders, EachNamesARegisteredScene) {
  const std::vector<std::string> names = scene_names();
  const std::set<std::string> known(names.begin(), names.end());
  for (const char* place :
       {"src/scenes", "shaders", "tests/scenes", "tests/golden", "tests/hard_cases"})
    for (const auto& e : fs::directory_iterator(source(place))) {
      const std::string name = e.path().filename().string();
      // tests/golden/shader_<example>/: the golden of a user's shader, examples/shaders/<example>.
      const std::string example = name.rfind("shader_", 0) == 0 ? name.substr(7) : "";
      if (!example.empty() && std::string(place) == "tests/golden") {
        const fs::path shaders = source("examples/shaders");
        EXPECT_TRUE(fs::exists(shaders / (example + ".glsl")) ||
                    fs::exists(shaders / (example + ".json")) ||
                    fs::is_directory(shaders / example))
            << place << "/" << name << "/ names no example in examples/shaders/";
      } else if (e.is_directory() && name != "common") {
        EXPECT_TRUE(known.count(name)) << place << "/" << name << "/ is not a registered scene";
      }
    }
}

}  // namespace
}  // namespace sdfreel
