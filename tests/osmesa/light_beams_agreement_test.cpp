// light_beams end to end through the sdfreel binary: the GLSL twin (shaders/light_beams/) renders
// frames of timelines/light_beams.toml bit for bit as the CPU backend does (scene-linear hashes
// equal), at the final preset (penumbra estimator) and the reference preset (exact visibility).
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "backends/osmesa/osmesa_platform.h"
#include "osmesa/run_binary.h"

namespace sdfreel {
namespace {

namespace fs = std::filesystem;
using test::run_sdfreel;

// The occluder entering, in the beams, and past the blue light (30 fps).
constexpr const char* FRAMES = "0,90,180,270";
constexpr size_t FRAME_COUNT = 4;
constexpr const char* RESOLUTION = "96x54";

std::vector<std::string> linear_hashes(const std::string& out) {
  const auto j = nlohmann::json::parse(test::read_text(out + "/manifest.json"));
  std::vector<std::string> all;
  for (const auto& f : j.at("frames")) all.push_back(f.at("linear_md5").get<std::string>());
  return all;
}

class LightBeamsBackends : public ::testing::Test {
 protected:
  void SetUp() override {
    try {
      OsmesaPlatform probe;  // the binary opens the same library
    } catch (const GlPlatformError& e) {
      GTEST_SKIP() << "OSMesa unavailable: " << e.what();
    }
    dir = test::scratch_dir(::testing::UnitTest::GetInstance()->current_test_info()->name());
  }
  void TearDown() override {
    if (!dir.empty() && !HasFailure()) fs::remove_all(dir);
  }
  std::string render(const std::string& backend, const std::string& quality) {
    const std::string out = dir + "/" + quality + "-" + backend;
    const std::string timeline = std::string(SDFREEL_SOURCE_DIR) + "/timelines/light_beams.toml";
    const test::BinaryResult r =
        run_sdfreel("render '" + timeline + "' --backend " + backend + " --quality " + quality +
                    " --samples 2 --frames " + FRAMES + " --resolution " + RESOLUTION +
                    " --no-video --out '" + out + "'");
    EXPECT_EQ(r.status, 0) << r.err;
    return out;
  }
  std::string dir;
};

TEST_F(LightBeamsBackends, FramesAreBitIdenticalToTheCpuBackend) {
  for (const char* quality : {"final", "reference"}) {
    const std::vector<std::string> cpu = linear_hashes(render("cpu", quality));
    const std::vector<std::string> gl = linear_hashes(render("osmesa", quality));
    ASSERT_EQ(cpu.size(), FRAME_COUNT) << quality;
    EXPECT_EQ(cpu, gl) << quality << ": the GLSL twin differs from the C++ scene; frames in "
                       << dir;
  }
}

}  // namespace
}  // namespace sdfreel
