// Every timeline under timelines/ end to end through the sdfreel binary, on both backends: the
// frames agree on display values (first, middle and last frame at 160x90), and the OSMesa backend
// renders them deterministically (repeated runs, LP_NUM_THREADS 1 and 2). Found by data: a new
// scene's timeline is checked without an edit here.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <vector>

#include "gl/gl_fixture.h"
#include "io/display_compare.h"
#include "io/frame_files.h"
#include "scenes/registry.h"
#include "support/run.h"
#include "support/scratch.h"
#include "timeline/timeline.h"

namespace sdfreel {
namespace {

namespace fs = std::filesystem;

constexpr double MAX_MEAN_DIFF = 0.5;  // in 1/255 of display values
constexpr double MAX_P999_DIFF = 4.0;
constexpr const char* RESOLUTION = "160x90";

std::vector<std::string> timeline_names() {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(test::source_path("timelines")))
    if (e.path().extension() == ".toml") names.push_back(e.path().stem().string());
  std::sort(names.begin(), names.end());
  return names;
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

// The scene-linear hash of every frame, in frame order.
std::vector<std::string> linear_hashes(const std::string& out) {
  const auto j = nlohmann::json::parse(test::read_file(out + "/manifest.json"));
  std::vector<std::string> all;
  for (const auto& f : j.at("frames")) all.push_back(f.at("linear_md5").get<std::string>());
  return all;
}

class TimelineBackends : public ::testing::TestWithParam<std::string> {
 protected:
  void SetUp() override {
    SDFREEL_SKIP_WITHOUT_GL();  // the binary opens the same library
    timeline = test::source_path("timelines/" + GetParam() + ".toml");
    const int n = load_timeline(all_scenes(), timeline, nullptr).frame_count();
    frames = {0, n / 2, n - 1};
    dir = test::scratch_dir("timeline-" + GetParam() + "-" +
                            ::testing::UnitTest::GetInstance()->current_test_info()->name());
  }
  // Outputs stay for inspection when the test failed (the agreement test's diff images).
  void TearDown() override {
    if (!dir.empty() && !HasFailure()) fs::remove_all(dir);
  }
  // Renders `which` frames at RESOLUTION into dir/<name>; returns the output folder.
  std::string render(const std::string& name, const std::vector<int>& which,
                     const std::string& backend, const std::string& env = "") {
    const std::string out = dir + "/" + name;
    const test::RunResult r = test::run_sdfreel(
        "render '" + timeline + "' --backend " + backend + " --frames " + frame_list(which) +
            " --resolution " + RESOLUTION + " --no-video --out '" + out + "'",
        ".", env);
    EXPECT_EQ(r.status, 0) << r.err;
    return out;
  }
  std::string timeline, dir;
  std::vector<int> frames;
};

TEST_P(TimelineBackends, FramesAgreeWithTheCpuBackend) {
  const std::string cpu = render("cpu", frames, "cpu");
  const std::string gl = render("gl", frames, "gl");
  const std::vector<std::string> cpu_linear = linear_hashes(cpu), gl_linear = linear_hashes(gl);
  ASSERT_EQ(cpu_linear.size(), frames.size());
  ASSERT_EQ(gl_linear.size(), frames.size());
  for (size_t k = 0; k < frames.size(); ++k) {
    const int i = frames[k];
    const ImageRGB16 a = read_png16(frame_png(cpu, i)), b = read_png16(frame_png(gl, i));
    const DisplayDifference d = compare_display(a, b);
    std::printf(
        "%s frame %d: mean %.4f/255, p99.9 %.3f/255, max %.2f/255, identical %.2f%%, "
        "linear frames %s\n",
        GetParam().c_str(), i, d.mean, d.p999, d.max, 100.0 * d.identical_share,
        cpu_linear[k] == gl_linear[k] ? "bit-identical" : "differ");
    if (d.mean >= MAX_MEAN_DIFF || d.p999 >= MAX_P999_DIFF) {
      const std::string diff = dir + "/diff-" + std::to_string(i) + ".png";
      write_png16_atomic(diff, difference_image(a, b, 16.0));
      ADD_FAILURE() << GetParam() << " frame " << i << ": backends differ by " << d.mean
                    << "/255 on average and " << d.p999 << "/255 at the 99.9th percentile; cpu "
                    << frame_png(cpu, i) << ", gl " << frame_png(gl, i)
                    << ", |difference| x16: " << diff;
    }
  }
}

TEST_P(TimelineBackends, OsmesaIsDeterministicAcrossRunsAndThreadCounts) {
  const std::vector<int> middle{frames[1]};
  const std::string one = render("lp1", middle, "gl", "LP_NUM_THREADS=1 ");
  const std::string two = render("lp2", middle, "gl", "LP_NUM_THREADS=2 ");
  const std::string again = render("lp2-again", middle, "gl", "LP_NUM_THREADS=2 ");
  const std::string md5 = test::read_file(one + "/frames.framemd5");
  ASSERT_FALSE(md5.empty());
  EXPECT_EQ(md5, test::read_file(two + "/frames.framemd5"));
  EXPECT_EQ(md5, test::read_file(again + "/frames.framemd5"));
  // The linear hashes too (the display hash could hide differences below 16-bit display steps).
  ASSERT_EQ(linear_hashes(one).size(), 1u);
  EXPECT_EQ(linear_hashes(one), linear_hashes(two));
  EXPECT_EQ(linear_hashes(one), linear_hashes(again));
}

INSTANTIATE_TEST_SUITE_P(Timelines, TimelineBackends, ::testing::ValuesIn(timeline_names()),
                         [](const ::testing::TestParamInfo<std::string>& i) { return i.param; });

}  // namespace
}  // namespace sdfreel
