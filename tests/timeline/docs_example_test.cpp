// docs/timeline.md is the users' reference: its complete example must parse, with every table
// and key it shows, so the page cannot drift from the parser. The README's flythrough, the first
// timeline a newcomer copies, must parse too.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "timeline/fixture.h"

namespace sdfreel::testing {
namespace {

// The fenced ```toml blocks of a Markdown file, in order.
std::vector<std::string> toml_blocks(const std::string& markdown) {
  std::vector<std::string> blocks;
  std::istringstream in(markdown);
  std::string line, block;
  bool inside = false;
  while (std::getline(in, line)) {
    if (!inside && line == "```toml") {
      inside = true;
      block.clear();
    } else if (inside && line == "```") {
      inside = false;
      blocks.push_back(block);
    } else if (inside) {
      block += line + "\n";
    }
  }
  return blocks;
}

std::string read_doc(const std::string& rel) {
  std::ifstream in(std::string(SDFREEL_SOURCE_DIR) + "/" + rel);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

class DocsExample : public TimelineFiles {};

TEST_F(DocsExample, TheTimelinePageExampleParsesWithEveryTable) {
  const std::vector<std::string> blocks = toml_blocks(read_doc("docs/timeline.md"));
  ASSERT_FALSE(blocks.empty()) << "docs/timeline.md has no ```toml example";
  const std::string& example = blocks.front();
  for (const char* table : {"[video]", "[output]", "[color]", "[time]", "[camera]", "[params]"})
    EXPECT_NE(example.find(table), std::string::npos) << "the example lacks " << table;
  const Timeline tl = load_timeline(all_scenes(), write(example), nullptr);
  EXPECT_EQ(tl.scene, "lantern_festival");
  EXPECT_EQ(tl.fps.num, 30000);
  EXPECT_EQ(tl.fps.den, 1001);
  EXPECT_EQ(tl.camera.keys.size(), 3u);
  EXPECT_TRUE(tl.camera.constant_speed);
  ASSERT_TRUE(tl.time.has_value());
  EXPECT_EQ(tl.params.size(), 4u);
}

TEST_F(DocsExample, TheReadmeFlythroughParses) {
  const std::vector<std::string> blocks = toml_blocks(read_doc("README.md"));
  ASSERT_FALSE(blocks.empty()) << "README.md has no ```toml flythrough";
  const Timeline tl = load_timeline(all_scenes(), write(blocks.front()), nullptr);
  EXPECT_EQ(tl.scene, "water_lily");
  EXPECT_EQ(tl.camera.keys.size(), 2u);
  EXPECT_EQ(tl.video, "my_flight.mp4");
}

}  // namespace
}  // namespace sdfreel::testing
