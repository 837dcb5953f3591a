// water_lily end to end through the sdfreel binary: the GLSL twin (shaders/water_lily/) renders
// frames of the scene's own timelines bit for bit like the CPU backend (scene-linear hashes), and
// so also within the display agreement rule.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <vector>

#include "backends/osmesa/osmesa_platform.h"
#include "io/frame_files.h"
#include "osmesa/image_compare.h"
#include "osmesa/run_binary.h"

namespace sdfreel {
namespace {

namespace fs = std::filesystem;
using test::run_sdfreel;

constexpr double MAX_MEAN_DIFF = 0.5;  // in 1/255 of display values
constexpr double MAX_P999_DIFF = 4.0;
constexpr const char* RESOLUTION = "96x54";

// Frames of the real timelines (30 fps): the drift's start and end, the flight between the
// flowers (close past petals, low over the pads) and its rise at the end.
struct Shot {
  std::string timeline;  // under timelines/
  std::vector<int> frames;
};
const std::vector<Shot>& shots() {
  static const std::vector<Shot> s = {{"water_lily", {0, 359}},
                                      {"water_lily_flythrough", {100, 300, 419}}};
  return s;
}

std::string frame_list(const std::vector<int>& frames) {
  std::string list;
  for (int f : frames) list += (list.empty() ? "" : ",") + std::to_string(f);
  return list;
}

std::string frame_png(const std::string& out, int i) {
  char name[32];
  std::snprintf(name, sizeof name, "/frames/%05d.png", i);
  return out + name;
}

std::vector<std::string> linear_hashes(const std::string& out) {
  const auto j = nlohmann::json::parse(test::read_text(out + "/manifest.json"));
  std::vector<std::string> all;
  for (const auto& f : j.at("frames")) all.push_back(f.at("linear_md5").get<std::string>());
  return all;
}

class WaterLilyBackends : public ::testing::Test {
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
  std::string render(const std::string& name, const Shot& shot, const std::string& backend) {
    const std::string out = dir + "/" + name;
    const std::string timeline =
        std::string(SDFREEL_SOURCE_DIR) + "/timelines/" + shot.timeline + ".toml";
    const test::BinaryResult r = run_sdfreel(
        "render '" + timeline + "' --backend " + backend + " --frames " + frame_list(shot.frames) +
        " --resolution " + RESOLUTION + " --samples 1 --no-video --out '" + out + "'");
    EXPECT_EQ(r.status, 0) << r.err;
    return out;
  }
  std::string dir;
};

TEST_F(WaterLilyBackends, FramesAreBitIdenticalToTheCpuBackend) {
  for (const Shot& shot : shots()) {
    const std::string cpu = render(shot.timeline + "-cpu", shot, "cpu");
    const std::string gl = render(shot.timeline + "-osmesa", shot, "osmesa");
    const std::vector<std::string> cpu_linear = linear_hashes(cpu), gl_linear = linear_hashes(gl);
    ASSERT_EQ(cpu_linear.size(), shot.frames.size());
    ASSERT_EQ(gl_linear.size(), shot.frames.size());
    for (size_t k = 0; k < shot.frames.size(); ++k) {
      const int i = shot.frames[k];
      const ImageRGB16 a = read_png16(frame_png(cpu, i)), b = read_png16(frame_png(gl, i));
      const test::DisplayDifference d = test::compare_display(a, b);
      std::printf("%s frame %d: mean %.4f/255, p99.9 %.3f/255, identical %.2f%%, linear %s\n",
                  shot.timeline.c_str(), i, d.mean, d.p999, 100.0 * d.identical_share,
                  cpu_linear[k] == gl_linear[k] ? "bit-identical" : "differ");
      EXPECT_EQ(cpu_linear[k], gl_linear[k]) << shot.timeline << " frame " << i;
      if (d.mean >= MAX_MEAN_DIFF || d.p999 >= MAX_P999_DIFF) {
        const std::string diff = dir + "/diff-" + shot.timeline + "-" + std::to_string(i) + ".png";
        write_png16_atomic(diff, test::difference_image(a, b, 16.0));
        ADD_FAILURE() << shot.timeline << " frame " << i << ": backends differ by " << d.mean
                      << "/255 on average; |difference| x16: " << diff;
      }
    }
  }
}

}  // namespace
}  // namespace sdfreel
