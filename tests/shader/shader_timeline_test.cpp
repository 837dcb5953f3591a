// The timeline's side of a user's shader: [video] shader, the [channels] tables (in the timeline
// or in channels.toml beside the tabs) and their refusals at the key that is wrong.
#include "shader/shader_timeline.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "io/png_file.h"
#include "render/srgb.h"
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
  for (const char* image : {"\"image\"", "\"self\""})
    EXPECT_NE(error(std::string("[channels.image]\niChannel1 = ") + image + "\n")
                  .find("t.toml:4:13: error: image iChannel1 reads the Image pass, which no "
                        "channel can read"),
              std::string::npos)
        << image;
  EXPECT_NE(error("[channels.image]\niChannel4 = \"buffer_a\"\n").find("unknown key 'iChannel4'"),
            std::string::npos);
  EXPECT_NE(error("[video2]\n").find("unknown table"), std::string::npos);
  EXPECT_NE(error("[shader]\noutput = \"hdr\"\n").find("t.toml:4:10: error:"), std::string::npos);
  EXPECT_NE(error("[video.adaptive]\n").find("not defined for a user's shader"), std::string::npos);
  EXPECT_NE(
      error("[shader]\ncube_size = 0\n").find("t.toml:4:13: error: shader.cube_size is Cube A"),
      std::string::npos);
  for (const char* every : {"-1", "2.5", "\"often\""})
    EXPECT_NE(error(std::string("[shader]\ncheckpoint_every = ") + every + "\n")
                  .find("t.toml:4:20: error: shader.checkpoint_every is a whole number"),
              std::string::npos)
        << every;
}

TEST_F(ShaderTimeline, ImageChannelsAreReadAtLoadWithTheirSrgbKey) {
  const uint8_t rgb[] = {188, 51, 0};
  const std::vector<unsigned char> png = encode_png(1, 1, 3, 8, rgb);
  test::write_file(dir + "/one.png", std::string(png.begin(), png.end()));
  const Timeline tl = load(
      "[channels.image]\niChannel0 = { texture = \"one.png\", srgb = true }\n"
      "iChannel1 = { texture = \"one.png\", filter = \"nearest\" }\n");
  const ShaderPass& image = project(tl).passes[1];
  const ChannelBinding& decoded = image.channels[0];
  ASSERT_TRUE(decoded.image);
  EXPECT_TRUE(decoded.srgb);
  EXPECT_EQ(decoded.image->pixels[0], srgb_to_linear(188.0f / 255.0f));
  const ChannelBinding& stored = image.channels[1];
  ASSERT_TRUE(stored.image);
  EXPECT_FALSE(stored.srgb);  // Shadertoy's default: the numbers stored
  EXPECT_EQ(stored.image->pixels[0], 188.0f / 255.0f);
  EXPECT_EQ(stored.filter, Filter::Nearest);
  EXPECT_EQ(stored.wrap, Wrap::Repeat);
  EXPECT_TRUE(stored.vflip);
}

TEST_F(ShaderTimeline, ImageChannelRefusalsNameTheFilePassAndChannel) {
  test::write_file(dir + "/broken.png", "not an image");
  EXPECT_NE(error("[channels.image]\niChannel3 = { texture = \"broken.png\" }\n")
                .find("t.toml:4:13: error: image iChannel3: " + dir +
                      "/broken.png: cannot read the image: "),
            std::string::npos);
  EXPECT_NE(
      error("[channels.image]\niChannel3 = { texture = \"gone.png\" }\n")
          .find("t.toml:4:13: error: image iChannel3: image file " + dir + "/gone.png not found"),
      std::string::npos);
  EXPECT_NE(error("[channels.image]\niChannel3 = { pass = \"buffer_a\", srgb = true }\n")
                .find("t.toml:4:41: error: channels.image.iChannel3.srgb applies to an image file"),
            std::string::npos);
  EXPECT_NE(error("[channels.image]\niChannel3 = { texture = \"one.png\", srgb = 1 }\n")
                .find("srgb must be true or false"),
            std::string::npos);
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
