// Shadertoy's JSON rendered end to end (docs/shaders.md): the site's export, the same shader in
// the public API's form and the same tabs as a folder give the same frames, bit for bit; a
// compile error names the JSON, the pass and the line within its code.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "gl/gl_cli_fixture.h"

namespace sdfreel {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using test::run_sdfreel;

class ShadertoyJsonRender : public test::GlCliTest {
 protected:
  void SetUp() override {
    GlCliTest::SetUp();
    if (IsSkipped()) return;
    site = json::parse(test::read_file(test::source_path("examples/shaders/comet_trail.json")));
  }
  // Renders `shader` (relative to dir) at 32x18, 6 frames; the framemd5's frame lines.
  std::vector<std::string> render(const std::string& shader, const std::string& out) {
    test::write_file(dir + "/" + out + ".toml",
                     "[video]\nshader = \"" + shader +
                         "\"\nfps = 10\nduration = 0.6\nresolution = [32, 18]\n\n"
                         "[output]\nframes = [\"png\"]\nvideo = \"\"\n");
    const test::RunResult r = run_sdfreel("render " + out + ".toml --out " + out, dir);
    EXPECT_EQ(r.status, 0) << r.err;
    return test::framemd5_frame_lines(dir + "/" + out + "/frames.framemd5");
  }
  json site;
};

// The public API's form of a site export: {"Shader": ...}, ctype/src, string ids.
json api_form(const json& site) {
  json shader = site.at(0);
  for (json& pass : shader["renderpass"]) {
    for (json& in : pass["inputs"]) {
      in["ctype"] = in["type"];
      in["src"] = in["filepath"];
      in.erase("type");
      in.erase("filepath");
      in["id"] = "id" + in["id"].dump();
    }
    for (json& out : pass["outputs"]) out["id"] = "id" + out["id"].dump();
  }
  return json{{"Shader", shader}};
}

TEST_F(ShadertoyJsonRender, SiteExportApiFormAndFolderGiveTheSameFrames) {
  test::write_file(dir + "/site.json", site.dump(1));
  test::write_file(dir + "/api.json", api_form(site).dump(1));
  fs::create_directories(dir + "/tabs");
  for (const json& pass : site.at(0).at("renderpass")) {
    const std::string type = pass.at("type");
    const std::string file = type == "buffer" ? "buffer_a" : type;
    test::write_file(dir + "/tabs/" + file + ".glsl", pass.at("code"));
  }
  test::write_file(dir + "/tabs/channels.toml",
                   "[channels.buffer_a]\niChannel0 = \"self\"\n"
                   "[channels.image]\niChannel0 = \"buffer_a\"\n");
  const std::vector<std::string> from_site = render("site.json", "site");
  ASSERT_EQ(from_site.size(), 6u);
  EXPECT_EQ(render("api.json", "api"), from_site);
  EXPECT_EQ(render("tabs", "tabs"), from_site);
}

TEST_F(ShadertoyJsonRender, CompileErrorNamesThePassAndItsLine) {
  for (json& pass : site.at(0)["renderpass"])
    if (pass["type"] == "buffer")
      pass["code"] = "// fine\nvoid mainImage(out vec4 c, in vec2 p) { c = nope; }\n";
  test::write_file(dir + "/broken.json", site.dump(1));
  test::write_file(dir + "/t.toml", "[video]\nshader = \"broken.json\"\n");
  const test::RunResult r = run_sdfreel("render t.toml", dir);
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("broken.json (buffer_a):2:"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir + "/output"));
}

}  // namespace
}  // namespace sdfreel
