// Shadertoy's JSON, both forms in circulation, read to the same passes and bindings; malformed
// JSON and inputs sdfreel does not take are refused with the file (and line) named.
#include "shader/shadertoy_json.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "support/scratch.h"
#include "timeline/timeline.h"

namespace sdfreel {
namespace {

// The public API's form: {"Shader": ...}, inputs with ctype/src, string output ids.
const char* kApi = R"({"Shader": {"info": {"id": "abcdef", "name": "feedback"}, "renderpass": [
  {"inputs": [{"id": "4dXGR8", "src": "/media/previz/buffer00.png", "ctype": "buffer",
               "channel": 0, "sampler": {"filter": "nearest", "wrap": "clamp", "vflip": "true"}}],
   "outputs": [{"id": "4sXGR8", "channel": 0}],
   "code": "void mainImage(out vec4 c, in vec2 p) { c = texture(iChannel0, p); }",
   "name": "Image", "description": "", "type": "image"},
  {"inputs": [{"id": "4dXGR8", "src": "/media/previz/buffer00.png", "ctype": "buffer",
               "channel": 1, "sampler": {"filter": "linear", "wrap": "repeat", "vflip": "true"}}],
   "outputs": [{"id": "4dXGR8", "channel": 0}],
   "code": "void mainImage(out vec4 c, in vec2 p) { c = vec4(twice(0.25)); }",
   "name": "Buffer A", "description": "", "type": "buffer"},
  {"inputs": [], "outputs": [], "code": "float twice(float x) { return 2.0 * x; }",
   "name": "Common", "description": "", "type": "common"}]}})";

// The site's own export: a list of shaders, inputs with type/filepath, numeric output ids.
const char* kSite = R"([{"ver": "0.1", "info": {"id": "-1", "name": "feedback"}, "renderpass": [
  {"inputs": [{"id": 257, "filepath": "/media/previz/buffer00.png", "type": "buffer",
               "channel": 0, "sampler": {"filter": "nearest", "wrap": "clamp", "vflip": "true"}}],
   "outputs": [{"id": 37, "channel": 0}],
   "code": "void mainImage(out vec4 c, in vec2 p) { c = texture(iChannel0, p); }",
   "name": "Image", "description": "", "type": "image"},
  {"inputs": [], "outputs": [], "code": "float twice(float x) { return 2.0 * x; }",
   "name": "Common", "description": "", "type": "common"},
  {"inputs": [{"id": 257, "filepath": "/media/previz/buffer00.png", "type": "buffer",
               "channel": 1, "sampler": {"filter": "linear", "wrap": "repeat", "vflip": "true"}}],
   "outputs": [{"id": 257, "channel": 0}],
   "code": "void mainImage(out vec4 c, in vec2 p) { c = vec4(twice(0.25)); }",
   "name": "Buf A", "description": "", "type": "buffer"}]}])";

std::string error_of(const std::string& text) {
  try {
    read_shadertoy_json("s.json", text, {});
  } catch (const InputError& e) {
    return e.formatted();
  }
  return "";
}

TEST(ShadertoyJson, BothFormsReadToTheSamePasses) {
  for (const char* text : {kApi, kSite}) {
    const ShaderProject p = read_shadertoy_json("s.json", text, {});
    EXPECT_EQ(p.common_source, "float twice(float x) { return 2.0 * x; }");
    ASSERT_EQ(p.passes.size(), 2u);
    const ShaderPass& a = p.passes[0];
    const ShaderPass& image = p.passes[1];
    EXPECT_EQ(a.kind, PassKind::BufferA);
    EXPECT_EQ(image.kind, PassKind::Image);
    EXPECT_NE(a.source.find("twice(0.25)"), std::string::npos);
    // Image reads Buffer A on channel 0, nearest and clamped; Buffer A reads itself on 1.
    EXPECT_EQ(image.channels[0].kind, ChannelKind::Pass);
    EXPECT_EQ(image.channels[0].pass, PassKind::BufferA);
    EXPECT_EQ(image.channels[0].filter, Filter::Nearest);
    EXPECT_EQ(image.channels[0].wrap, Wrap::Clamp);
    EXPECT_EQ(image.channels[1].kind, ChannelKind::None);
    EXPECT_EQ(a.channels[1].kind, ChannelKind::Pass);
    EXPECT_EQ(a.channels[1].pass, PassKind::BufferA);
    EXPECT_EQ(a.channels[1].wrap, Wrap::Repeat);
    EXPECT_TRUE(p.has_feedback());
  }
}

TEST(ShadertoyJson, TextureInputsAreFoundBesideTheJsonThenInTheTextureFolders) {
  const std::string dir = test::scratch_dir("shadertoy-json-textures");
  std::filesystem::create_directories(dir + "/media");
  test::write_file(dir + "/noise.png", "png bytes");
  test::write_file(dir + "/media/wood.png", "png bytes");
  const std::string text = R"({"Shader": {"renderpass": [{"type": "image", "code": "", "inputs": [
      {"ctype": "texture", "src": "/media/a/noise.png", "channel": 0,
       "sampler": {"filter": "mipmap", "wrap": "repeat", "vflip": "false", "srgb": "true"}},
      {"ctype": "texture", "src": "/media/a/wood.png", "channel": 3}]}]}})";
  const ShaderProject p = read_shadertoy_json(dir + "/s.json", text, {dir + "/media"});
  const ChannelBinding& noise = p.passes[0].channels[0];
  EXPECT_EQ(noise.kind, ChannelKind::Texture);
  EXPECT_EQ(noise.files, std::vector<std::string>({dir + "/noise.png"}));
  EXPECT_FALSE(noise.vflip);
  EXPECT_TRUE(noise.srgb);
  const ChannelBinding& wood = p.passes[0].channels[3];
  EXPECT_EQ(wood.files, std::vector<std::string>({dir + "/media/wood.png"}));
  EXPECT_TRUE(wood.vflip);  // Shadertoy's default for a texture
  EXPECT_FALSE(wood.srgb);  // as stored, unless the sampler says srgb
  EXPECT_EQ(wood.filter, Filter::Mipmap);
  EXPECT_EQ(wood.wrap, Wrap::Repeat);
}

TEST(ShadertoyJson, CubemapInputsAreSixFaceFilesAndCubeAIsAPass) {
  const std::string dir = test::scratch_dir("shadertoy-json-cubemaps");
  const std::vector<std::string> names = {"sky.jpg",   "sky_1.jpg", "sky_2.jpg",
                                          "sky_3.jpg", "sky_4.jpg", "sky_5.jpg"};
  for (const std::string& n : names) test::write_file(dir + "/" + n, "jpeg bytes");
  const std::string text = R"({"Shader": {"renderpass": [
      {"type": "cubemap", "name": "Cube A", "code": "", "outputs": [{"id": "4dX3Rr", "channel": 0}],
       "inputs": [{"ctype": "cubemap", "src": "/media/a/sky.jpg", "channel": 1,
                   "sampler": {"filter": "linear", "srgb": "true"}}]},
      {"type": "image", "code": "", "inputs": [{"ctype": "cubemap", "id": "4dX3Rr", "channel": 0}]}]}})";
  const ShaderProject p = read_shadertoy_json(dir + "/s.json", text, {});
  ASSERT_EQ(p.passes.size(), 2u);
  EXPECT_EQ(p.passes[0].kind, PassKind::CubeA);
  const ChannelBinding& sky = p.passes[0].channels[1];
  EXPECT_EQ(sky.kind, ChannelKind::Cubemap);
  std::vector<std::string> want;
  for (const std::string& n : names) want.push_back(dir + "/" + n);
  EXPECT_EQ(sky.files, want);
  EXPECT_TRUE(sky.srgb);
  EXPECT_EQ(sky.filter, Filter::Linear);
  const ChannelBinding& cube = p.passes[1].channels[0];
  EXPECT_EQ(cube.kind, ChannelKind::Pass);
  EXPECT_EQ(cube.pass, PassKind::CubeA);
  std::filesystem::remove(dir + "/sky_4.jpg");
  try {
    read_shadertoy_json(dir + "/s.json", text, {});
    FAIL() << "a missing face was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("cube_a iChannel1: texture /media/a/sky_4.jpg: no file "
                                         "sky_4.jpg"),
              std::string::npos)
        << e.what();
  }
}

TEST(ShadertoyJson, RefusalsNameWhatIsWrong) {
  const std::string bad = error_of("{\"Shader\": {\n  \"renderpass\": [,]}}");
  EXPECT_NE(bad.find("s.json:2:"), std::string::npos) << bad;
  EXPECT_NE(bad.find("not valid JSON"), std::string::npos) << bad;
  EXPECT_NE(error_of("{\"name\": 1}").find("not a Shadertoy export"), std::string::npos);
  // Found by fuzz_shadertoy_json: these threw nlohmann's own exceptions (exit 1, or terminate).
  EXPECT_NE(error_of("[1E400]").find("not valid JSON"), std::string::npos);
  EXPECT_NE(error_of(R"({"Shader": {"renderpass": [{"type": "image", "code": "", "inputs": [
              {"ctype": "buffer", "channel": "zero"}]}]}})")
                .find("not a Shadertoy export as sdfreel reads it"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"Shader": {"renderpass": [{"type": "sound", "code": ""}]}})")
                .find("Sound tab is not supported"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"Shader": {"renderpass": [{"type": "image", "code": "", "inputs": [
              {"ctype": "keyboard", "channel": 0}]}]}})")
                .find("image iChannel0: input of type 'keyboard' is not supported"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"Shader": {"renderpass": [{"type": "image", "code": "", "inputs": [
              {"ctype": "texture", "src": "/media/a/noise.png", "channel": 2}]}]}})")
                .find("image iChannel2: texture /media/a/noise.png: no file noise.png beside the "
                      "JSON"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"Shader": {"renderpass": [{"type": "image", "code": "", "inputs": [
              {"ctype": "buffer", "id": "nope", "channel": 0}]}]}})")
                .find("reads a buffer that no render pass writes"),
            std::string::npos);
}

}  // namespace
}  // namespace sdfreel
