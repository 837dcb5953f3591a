// The osmesa backend through the sdfreel binary, on a small sdf_morph timeline: it names Mesa in
// the manifest, and fails cleanly (exit 1, a message) without OSMesa or with a broken shader.
// (Agreement with the CPU backend and determinism, for every scene: agreement_test.cpp and
// timeline_agreement_test.cpp.)
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "backends/osmesa/osmesa_platform.h"
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

class OsmesaCli : public ::testing::Test {
 protected:
  void SetUp() override {
    try {
      OsmesaPlatform probe;  // the binary opens the same library
    } catch (const GlPlatformError& e) {
      GTEST_SKIP() << "OSMesa unavailable: " << e.what();
    }
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

TEST_F(OsmesaCli, ManifestNamesBackendMesaAndRenderer) {
  const std::string out = render("manifest", "osmesa");
  const auto j = nlohmann::json::parse(test::read_file(out + "/manifest.json"));
  EXPECT_EQ(j.at("backend"), "osmesa");
  const auto& v = j.at("versions");
  ASSERT_TRUE(v.contains("osmesa.mesa")) << v.dump();
  EXPECT_NE(v.at("osmesa.mesa").get<std::string>(), "unknown");
  EXPECT_NE(
      v.at("osmesa.gl_version").get<std::string>().find(v.at("osmesa.mesa").get<std::string>()),
      std::string::npos);
  EXPECT_FALSE(v.at("osmesa.gl_renderer").get<std::string>().empty());
  // The osmesa backend counts SDF evaluations in the shader.
  for (const auto& f : j.at("frames")) EXPECT_GT(f.at("sdf_evals_per_pixel").get<double>(), 1.0);
}

TEST_F(OsmesaCli, MissingOsmesaLibraryIsAClearErrorNotACrash) {
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

TEST_F(OsmesaCli, ShaderErrorNamesFileAndLineAndExitsWithOne) {
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
      run_sdfreel("still '" + timeline + "' --time 0 -o '" + dir + "/x.png' --backend osmesa", ".",
                  "SDFREEL_SHADER_DIR='" + shaders + "' ");
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_NE(r.err.find(shaders + "/sdf_morph/sdf_morph.glsl:" + std::to_string(line) + ":"),
            std::string::npos)
      << r.err;
}

}  // namespace
}  // namespace sdfreel
