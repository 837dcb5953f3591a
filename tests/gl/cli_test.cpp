// The GL backend through the sdfreel binary, on a small sdf_morph timeline: it names its platform,
// device, Mesa and renderer in the manifest, and fails cleanly (exit 1, a message) without its
// library, on a device that is not there, or with a broken shader.
// (Agreement with the CPU backend and determinism, for every scene: agreement_test.cpp and
// timeline_agreement_test.cpp.)
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "gl/gl_fixture.h"
#include "support/run.h"
#include "support/scratch.h"

namespace sdfreel {
namespace {

namespace fs = std::filesystem;
using test::run_sdfreel;

// 160x90, 3 frames at 10 fps with a 0.5 s morph period: torus, half-way, mug; the camera moves.
std::string small_timeline() {
  return "[video]\nscene = \"sdf_morph\"\nfps = 10\nduration = 0.3\nresolution = [160, 90]\n"
         "samples = 2\nquality = \"final\"\n\n"
         "[output]\ndir = \"out\"\nframes = [\"png\"]\nvideo = \"\"\n\n"
         "[camera]\ninterpolation = \"linear\"\nkeys = [\n"
         "  { t = 0.0, position = [0.0, 1.45, -3.4], target = [0.0, 0.72, 0.0], fov = 40.0 },\n"
         "  { t = 0.3, position = [2.2, 1.9, -2.6], target = [0.0, 0.7, 0.0], fov = 36.0, roll = "
         "4.0 },\n"
         "]\n\n[params]\nmorph_period = 0.5\n";
}

class GlCli : public ::testing::Test {
 protected:
  void SetUp() override {
    SDFREEL_SKIP_WITHOUT_GL();  // the binary opens the same library
    dir = test::scratch_dir(::testing::UnitTest::GetInstance()->current_test_info()->name());
    timeline = dir + "/t.toml";
    test::write_file(timeline, small_timeline());
  }
  // Outputs stay for inspection when the test failed.
  void TearDown() override {
    if (!dir.empty() && !HasFailure()) fs::remove_all(dir);
  }
  // Renders the timeline into dir/<name>; returns the output folder.
  std::string render(const std::string& name, const std::string& backend,
                     const std::string& env = "") {
    const std::string out = dir + "/" + name;
    const test::RunResult r = run_sdfreel(
        "render '" + timeline + "' --backend " + backend + " --out '" + out + "'", ".", env);
    EXPECT_EQ(r.status, 0) << r.err;
    return out;
  }
  std::string dir, timeline;
};

TEST_F(GlCli, ManifestNamesPlatformDeviceMesaAndRenderer) {
  const std::string out = render("manifest", "gl");
  const auto j = nlohmann::json::parse(test::read_file(out + "/manifest.json"));
  const std::string platform = j.at("backend");
  const std::string asked = resolved({}).platform;
  if (asked == "auto")
    EXPECT_TRUE(platform == "egl" || platform == "osmesa") << platform;
  else
    EXPECT_EQ(platform, asked);
  const auto& v = j.at("versions");
  const std::string p = platform + ".";
  ASSERT_TRUE(v.contains(p + "mesa")) << v.dump();
  EXPECT_EQ(v.at(p + "platform"), platform);
  EXPECT_EQ(v.at(p + "device"), "software");
  EXPECT_NE(v.at(p + "mesa").get<std::string>(), "unknown");
  EXPECT_NE(v.at(p + "gl_version").get<std::string>().find(v.at(p + "mesa").get<std::string>()),
            std::string::npos);
  EXPECT_EQ(v.at(p + "gl_renderer").get<std::string>().rfind("llvmpipe", 0), 0u) << v.dump();
  // The GL backend counts SDF evaluations in the shader.
  for (const auto& f : j.at("frames")) EXPECT_GT(f.at("sdf_evals_per_pixel").get<double>(), 1.0);
}

TEST_F(GlCli, BackendOsmesaKeepsItsNameInTheManifest) {
  std::string why;
  const bool have_osmesa = test::try_gl_platform(&why, "osmesa") != nullptr;
  if (!have_osmesa) GTEST_SKIP() << why;
  const std::string out = render("legacy", "osmesa");
  const auto j = nlohmann::json::parse(test::read_file(out + "/manifest.json"));
  EXPECT_EQ(j.at("backend"), "osmesa");
  EXPECT_EQ(j.at("versions").at("osmesa.platform"), "osmesa");
}

TEST_F(GlCli, ADeviceThatIsNotThereNamesTheDevicesThatAre) {
  std::string why;
  const bool have_egl = test::try_gl_platform(&why, "egl") != nullptr;
  if (!have_egl) GTEST_SKIP() << why;
  const test::RunResult r = run_sdfreel(
      "still '" + timeline + "' --time 0 -o '" + dir + "/x.png' --backend egl --gl-device 99", ".");
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_NE(r.err.find("no EGL device '99'"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("software"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir + "/x.png"));
  // The variable chooses as the option does.
  const test::RunResult env =
      run_sdfreel("still '" + timeline + "' --time 0 -o '" + dir + "/x.png' --backend egl", ".",
                  "SDFREEL_GL_DEVICE=99 ");
  EXPECT_EQ(env.status, 1) << env.err;
  EXPECT_NE(env.err.find("no EGL device '99'"), std::string::npos) << env.err;
}

TEST_F(GlCli, MissingEglLibraryIsAClearErrorNotACrash) {
  const std::string env = "SDFREEL_EGL_LIBRARY=/nonexistent/libEGL.so.1 ";
  const test::RunResult r = run_sdfreel(
      "still '" + timeline + "' --time 0 -o '" + dir + "/x.png' --backend egl", ".", env);
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_NE(r.err.find("EGL is not available"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir + "/x.png"));
}

TEST_F(GlCli, MissingOsmesaLibraryIsAClearErrorNotACrash) {
  const std::string env = "SDFREEL_OSMESA_LIBRARY=/nonexistent/libOSMesa.so.8 ";
  const test::RunResult r = run_sdfreel(
      "still '" + timeline + "' --time 0 -o '" + dir + "/x.png' --backend osmesa", ".", env);
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_NE(r.err.find("OSMesa is not available"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir + "/x.png"));
  // The CPU backend does not need the library.
  const test::RunResult cpu = run_sdfreel(
      "still '" + timeline + "' --time 0 -o '" + dir + "/y.png' --backend cpu", ".", env);
  EXPECT_EQ(cpu.status, 0) << cpu.err;
}

// `sdfreel devices` lists the software device with the renderer its context reports, and the
// index shown is one --gl-device accepts.
TEST_F(GlCli, DevicesListsTheSoftwareDeviceAndItRenders) {
  const test::RunResult r = run_sdfreel("devices --json", ".");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  std::string renderer;
  for (const auto& d : j.at("egl").at("devices"))
    if (d.at("software").get<bool>()) {
      ASSERT_TRUE(d.at("context").contains("renderer")) << d.dump();
      renderer = d.at("context").at("renderer");
      const std::string index = std::to_string(d.at("index").get<int>());
      const test::RunResult still =
          run_sdfreel("still '" + timeline + "' --time 0 -o '" + dir +
                          "/by-index.png' --backend egl --gl-device " + index,
                      ".");
      EXPECT_EQ(still.status, 0) << still.err;
    }
  if (j.at("egl").contains("surfaceless")) renderer = j["egl"]["surfaceless"].value("renderer", "");
  if (renderer.empty() && j.at("osmesa").contains("renderer")) renderer = j["osmesa"]["renderer"];
  EXPECT_EQ(renderer.rfind("llvmpipe", 0), 0u) << j.dump(2);
  const test::RunResult text = run_sdfreel("devices", ".");
  EXPECT_EQ(text.status, 0) << text.err;
  EXPECT_NE(text.out.find("llvmpipe"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("OSMesa"), std::string::npos) << text.out;
}

// Without any GL library nothing renders: devices says why and exits 1.
TEST_F(GlCli, DevicesWithoutLibrariesSaysWhyAndExitsWithOne) {
  const test::RunResult r = run_sdfreel("devices", ".",
                                        "SDFREEL_EGL_LIBRARY=/nonexistent/libEGL.so.1 "
                                        "SDFREEL_OSMESA_LIBRARY=/nonexistent/libOSMesa.so.8 ");
  EXPECT_EQ(r.status, 1) << r.out;
  EXPECT_NE(r.out.find("EGL is not available"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("OSMesa is not available"), std::string::npos) << r.out;
}

TEST_F(GlCli, ShaderErrorNamesFileAndLineAndExitsWithOne) {
  // A copy of the shader folder whose sdf_morph/sdf_morph.glsl has an undeclared name on a known
  // line.
  const std::string shaders = dir + "/shaders";
  fs::copy(fs::path(SDFREEL_SOURCE_DIR) / "shaders", shaders, fs::copy_options::recursive);
  std::string text = test::read_file(shaders + "/sdf_morph/sdf_morph.glsl");
  int line = 1;
  for (char c : text) line += c == '\n';
  text += "float broken_on_purpose() { return undeclared_name; }\n";
  test::write_file(shaders + "/sdf_morph/sdf_morph.glsl", text);
  const test::RunResult r =
      run_sdfreel("still '" + timeline + "' --time 0 -o '" + dir + "/x.png' --backend gl", ".",
                  "SDFREEL_SHADER_DIR='" + shaders + "' ");
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_NE(r.err.find(shaders + "/sdf_morph/sdf_morph.glsl:" + std::to_string(line) + ":"),
            std::string::npos)
      << r.err;
}

}  // namespace
}  // namespace sdfreel
