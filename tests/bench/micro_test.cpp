// The micro-benchmark harness on a fake scene (a sphere): rates of both paths, the lane identity
// check, the sample points, and `sdfreel bench --micro` end to end.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "bench/micro_bench.h"
#include "bench/micro_check.h"
#include "bench/micro_report.h"
#include "sdf/sdf.h"

namespace sdfreel::bench {
namespace {

// A sphere whose radius prepare() reads from the frame; `broken_lane` >= 0 puts that lane of each
// eight one ulp off, as a lane function with one wrong operation would.
class FakeSphereScene : public Scene {
 public:
  explicit FakeSphereScene(int broken_lane = -1) : broken_lane_(broken_lane) {}
  void prepare(const FrameContext& ctx) override { radius_ = 1.0f + 0.25f * float(ctx.scene_time); }
  glm::vec3 radiance(const Ray&, RayStats&) const override { return glm::vec3(0.0f); }
  std::vector<DistanceFunction> distance_functions() const override {
    DistanceFunction f;
    f.name = "sdSphere";
    f.scalar = [this](const float* x, const float* y, const float* z, float* d, int n) {
      for (int i = 0; i < n; ++i) d[i] = sdSphere(glm::vec3(x[i], y[i], z[i]), radius_);
    };
    f.lanes = [this](const float* x, const float* y, const float* z, float* d, int n) {
      for (int i = 0; i < n; i += LANES) {
        F8 r = sdSphere(V3x8(load8(x + i), load8(y + i), load8(z + i)), radius_);
        if (broken_lane_ >= 0) r[broken_lane_] = std::nextafter(r[broken_lane_], 1e30f);
        store8(d + i, r);
      }
    };
    return {f};
  }

 private:
  int broken_lane_;
  float radius_ = 0.0f;
};

MicroTarget fake_target(int broken_lane) {
  FrameContext ctx;
  ctx.scene_time = 2.0;
  auto scene = std::make_shared<FakeSphereScene>(broken_lane);
  scene->prepare(ctx);
  MicroTarget t;
  t.scene = "fake";
  t.owner = scene;
  t.functions = scene->distance_functions();
  t.points = camera_sample_points(make_camera_basis(CameraPose{}), MICRO_VIEW_WIDTH,
                                  MICRO_VIEW_HEIGHT, MICRO_MAX_DISTANCE, MICRO_POINT_SEED);
  return t;
}

// Tiny timings: the test checks the plumbing, not the speed.
const MicroOptions QUICK{2, 0.01};

TEST(MicroBench, CorrectLanesGiveBothRatesAndPassTheCheck) {
  const std::vector<MicroTarget> targets = {fake_target(-1)};
  EXPECT_FALSE(first_lane_mismatch(targets[0].functions[0], targets[0].points).has_value());
  const std::vector<MicroRow> rows = run_micro_benchmarks(targets, QUICK);
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_EQ(rows[0].scene, "fake");
  EXPECT_EQ(rows[0].function, "sdSphere");
  EXPECT_EQ(rows[0].points, MICRO_VIEW_WIDTH * MICRO_VIEW_HEIGHT);
  EXPECT_GT(rows[0].scalar_evals_per_s, 0.0);
  EXPECT_GT(rows[0].lanes_evals_per_s, 0.0);
  EXPECT_TRUE(std::isfinite(rows[0].lanes_over_scalar()));
}

TEST(MicroBench, OneLaneOffFailsTheCheckBeforeTiming) {
  const std::vector<MicroTarget> targets = {fake_target(3)};
  const auto m = first_lane_mismatch(targets[0].functions[0], targets[0].points);
  ASSERT_TRUE(m.has_value());
  EXPECT_EQ(m->index, 3);  // lane 3 of the first eight points
  EXPECT_NE(m->scalar, m->lanes);
  try {
    run_micro_benchmarks(targets, QUICK);
    FAIL() << "a lane mismatch must stop the micro-benchmarks";
  } catch (const LaneMismatchError& e) {
    EXPECT_NE(std::string(e.what()).find("fake/sdSphere"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("point 3 "), std::string::npos) << e.what();
  }
}

TEST(MicroBench, ALaneLeftUnwrittenFailsTheCheck) {
  MicroTarget t = fake_target(-1);
  const auto full = t.functions[0].lanes;
  t.functions[0].lanes = [full](const float* x, const float* y, const float* z, float* d, int n) {
    full(x, y, z, d, n - LANES);  // the last eight points never written
  };
  const auto m = first_lane_mismatch(t.functions[0], t.points);
  ASSERT_TRUE(m.has_value());
  EXPECT_EQ(m->index, t.points.size() - LANES);
}

TEST(MicroBench, SamplePointsLieOnCameraRaysWithinTheDistance) {
  const CameraBasis cam = make_camera_basis(CameraPose{});
  const SamplePoints a = camera_sample_points(cam, 64, 36, 30.0f, 1);
  const SamplePoints b = camera_sample_points(cam, 64, 36, 30.0f, 1);
  const SamplePoints c = camera_sample_points(cam, 64, 36, 30.0f, 2);
  ASSERT_EQ(a.size(), 64 * 36);
  EXPECT_EQ(a.x, b.x);
  EXPECT_NE(a.x, c.x);
  float lo = 1e30f, hi = 0.0f;
  for (int i = 0; i < a.size(); ++i) {
    const glm::vec3 v = glm::vec3(a.x[i], a.y[i], a.z[i]) - cam.origin;
    const float t = glm::length(v);
    lo = std::min(lo, t);
    hi = std::max(hi, t);
    const glm::vec3 dir = primary_ray_dir(cam, float(i % 64) + 0.5f, float(i / 64) + 0.5f, 64, 36);
    if (t > 1e-3f) {
      EXPECT_GT(glm::dot(v / t, dir), 0.99999f) << "point " << i;
    }
  }
  EXPECT_GE(lo, 0.0f);
  EXPECT_LT(hi, 30.0f * 1.0001f);
  EXPECT_LT(lo, 1.0f);  // spread over the whole range
  EXPECT_GT(hi, 29.0f);
  EXPECT_THROW(camera_sample_points(cam, 5, 3, 30.0f, 1), std::invalid_argument);
}

TEST(MicroBench, TableAndCsvHaveOneLinePerFunction) {
  const std::vector<MicroRow> rows = {{"s", "f", 16, 2.0e6, 8.0e6}};
  EXPECT_NE(format_micro_table(rows).find("| s | f | 2e+06 | 8e+06 | 4.00x |"), std::string::npos)
      << format_micro_table(rows);
  std::ostringstream csv;
  write_micro_csv(csv, rows);
  EXPECT_EQ(csv.str(),
            "scene,function,points,scalar_evals_per_s,lanes_evals_per_s,lanes_over_scalar\n"
            "s,f,16,2e+06,8e+06,4.0000\n");
}

int run_binary(const std::string& args) {
  const std::string cmd = std::string(SDFREEL_BINARY) + " " + args + " >/dev/null 2>&1";
  const int s = std::system(cmd.c_str());
  return WIFEXITED(s) ? WEXITSTATUS(s) : -1;
}

// The real-scene path: whatever functions the scene lists (maybe none yet), a csv with its header.
TEST(MicroBenchCommand, WritesMicroCsvAndRejectsUnknownScenes) {
  const auto dir =
      std::filesystem::temp_directory_path() / ("sdfreel_micro_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  EXPECT_EQ(run_binary("bench --micro sdf_morph --repetitions 1 --micro-min-time 0.01 --out " +
                       dir.string()),
            0);
  std::ifstream f(dir / "micro.csv");
  std::string header;
  std::getline(f, header);
  EXPECT_EQ(header, "scene,function,points,scalar_evals_per_s,lanes_evals_per_s,lanes_over_scalar");
  for (std::string line; std::getline(f, line);) EXPECT_EQ(line.rfind("sdf_morph,", 0), 0u) << line;
  EXPECT_EQ(run_binary("bench --micro no_such_scene --out " + dir.string()), 2);
  EXPECT_EQ(run_binary("bench --micro sdf_morph --micro-min-time 0 --out " + dir.string()), 2);
  std::filesystem::remove_all(dir);
}

// --only keeps the functions whose names start with a prefix (what scripts/count-flops.sh runs
// under callgrind, one function at a time); a prefix that keeps none is a usage error.
TEST(MicroBenchCommand, OnlyKeepsTheNamedFunctions) {
  const auto dir =
      std::filesystem::temp_directory_path() / ("sdfreel_micro_only_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  EXPECT_EQ(run_binary("bench --micro sdf_morph lantern_festival --only mapObj,sdfW --repetitions "
                       "1 --micro-min-time 0.01 --out " +
                       dir.string()),
            0);
  std::ifstream f(dir / "micro.csv");
  std::vector<std::string> kept;
  for (std::string line; std::getline(f, line);)  // the first two fields: scene, function
    kept.push_back(line.substr(0, line.find(',', line.find(',') + 1)));
  EXPECT_EQ(kept, (std::vector<std::string>{"scene,function", "sdf_morph,mapObject",
                                            "lantern_festival,sdfWater"}));
  EXPECT_EQ(run_binary("bench --micro sdf_morph --only sdfWater --out " + dir.string()), 2);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace sdfreel::bench
