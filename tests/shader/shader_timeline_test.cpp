// The timeline's side of a user's shader: [video] shader, the [channels] tables (in the timeline
// or in channels.toml beside the tabs) and their refusals at the key that is wrong.
#include "shader/shader_timeline.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "scenes/scene.h"
#include "shader/shader_project.h"
#include "support/scratch.h"
#include "timeline/timeline.h"

namespace sdfreel {
namespace {

const char* kImage = "void mainImage(out vec4 c, in vec2 p) { c = vec4(1.0); }\n";

class ShaderTimeline : public ::testing::Test {
 protected:
  void SetUp() override {
    dir = test::scratch_dir(::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::create_directories(dir + "/tabs");
    test::write_file(dir + "/tabs/image.glsl", kImage);
    test::write_file(dir + "/tabs/buffer_a.glsl", kImage);
  }
  Timeline load(const std::string& extra) {
    test::write_file(dir + "/t.toml", "[video]\nshader = \"tabs\"\n" + extra);
    ShaderTimelineLoader loader;
    return load_timeline({}, dir + "/t.toml", nullptr, &loader);
  }
  std::string error(const std::string& extra) {
    try {
      load(extra);
    } catch (const InputError& e) {
      return e.formatted();
    }
    return "";
  }
  const ShaderProject& project(const Timeline& tl) { return *tl.shader_scene->shader_project; }
  std::string dir;
};

TEST_F(ShaderTimeline, ChannelsBindPassesWithShadertoysDefaults) {
  const Timeline tl = load(
      "[channels.buffer_a]\niChannel0 = \"self\"\n"
      "[channels.image]\niChannel0 = \"buffer_a\"\n"
      "iChannel2 = { pass = \"buffer_a\", filter = \"mipmap\", wrap = \"repeat\" }\n");
  EXPECT_EQ(tl.samples, 1);  // Shadertoy's one sample a pixel
  EXPECT_EQ(tl.scene, "shader:tabs");
  const ShaderProject& p = project(tl);
  ASSERT_EQ(p.passes.size(), 2u);
  const ChannelBinding& self = p.passes[0].channels[0];
  EXPECT_EQ(self.kind, ChannelKind::Pass);
  EXPECT_EQ(self.pass, PassKind::BufferA);
  const ChannelBinding& a = p.passes[1].channels[0];
  EXPECT_EQ(a.pass, PassKind::BufferA);
  EXPECT_EQ(a.filter, Filter::Linear);  // a buffer's default: linear, clamped
  EXPECT_EQ(a.wrap, Wrap::Clamp);
  EXPECT_EQ(p.passes[1].channels[1].kind, ChannelKind::None);
  EXPECT_EQ(p.passes[1].channels[2].filter, Filter::Mipmap);
  EXPECT_EQ(p.passes[1].channels[2].wrap, Wrap::Repeat);
  EXPECT_TRUE(p.has_feedback());
}

TEST_F(ShaderTimeline, ChannelsTomlBesideTheTabsAndTheTimelineOverIt) {
  test::write_file(dir + "/tabs/channels.toml",
                   "[channels.image]\niChannel0 = \"buffer_a\"\niChannel1 = \"buffer_a\"\n");
  const Timeline tl = load("[channels.image]\niChannel1 = \"none\"\n");
  const ShaderProject& p = project(tl);
  EXPECT_EQ(p.passes[1].channels[0].kind, ChannelKind::Pass);
  EXPECT_EQ(p.passes[1].channels[1].kind, ChannelKind::None);
  EXPECT_FALSE(p.has_feedback());  // Image reads this frame's Buffer A: no past needed
}

TEST_F(ShaderTimeline, RefusalsPointAtTheKey) {
  EXPECT_EQ(error("[channels.buffer_b]\niChannel0 = \"self\"\n"),
            dir +
                "/t.toml:3:1: error: [channels.buffer_b]: this shader has no buffer_b pass (it "
                "has buffer_a and image)");
  EXPECT_NE(error("[channels.image]\niChannel0 = \"bufer_a\"\n").find("t.toml:4:13: error:"),
            std::string::npos);
  EXPECT_NE(error("[channels.image]\niChannel0 = \"buffer_c\"\n")
                .find("image iChannel0 reads buffer_c, which this shader does not have"),
            std::string::npos);
  EXPECT_NE(error("[channels.image]\niChannel4 = \"buffer_a\"\n").find("unknown key 'iChannel4'"),
            std::string::npos);
  EXPECT_NE(error("[video2]\n").find("unknown table"), std::string::npos);
  EXPECT_NE(error("[shader]\noutput = \"hdr\"\n").find("t.toml:4:10: error:"), std::string::npos);
  EXPECT_NE(error("[video.adaptive]\n").find("not defined for a user's shader"), std::string::npos);
}

TEST_F(ShaderTimeline, BuiltInScenesRefuseTheShaderTables) {
  test::write_file(dir + "/s.toml",
                   "[video]\nscene = \"x\"\n[channels.image]\niChannel0 = \"none\"\n");
  ShaderTimelineLoader loader;
  try {
    load_timeline({}, dir + "/s.toml", nullptr, &loader);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("belongs to a timeline of a user's shader"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace sdfreel
