// Issue 17 item 6: with speed = "constant", the arc-length table is built once, not per sample,
// and stays bounded however many keys there are.
#include <gtest/gtest.h>

#include <chrono>

#include "timeline/timeline.h"

namespace sdfreel {
namespace {

CameraPath long_path(int keys) {
  CameraPath path;
  path.constant_speed = true;
  for (int i = 0; i < keys; ++i) {
    const double a = i * 0.01;
    path.keys.push_back(CameraKey{
        double(i),
        CameraPose{{10 * std::cos(a), 1.0 + 0.001 * i, 10 * std::sin(a)}, {0, 0, 0}, 40, 0}});
  }
  return path;
}

double seconds_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

// 20,000 keys: before the fix each sample built a 20-million-entry table (seconds and 320 MB per
// sample). Now prepare() builds about 2^20 entries once and 200 samples are binary searches.
TEST(CameraPathCost, ManyKeysConstantSpeedSamplesCheaplyAfterPrepare) {
  CameraPath path = long_path(20000);
  const auto start = std::chrono::steady_clock::now();
  path.prepare();
  const double prepare_s = seconds_since(start);
  const auto sampling = std::chrono::steady_clock::now();
  double sum = 0.0;
  for (int i = 0; i < 200; ++i) sum += path.sample(i * 99.9, {}).position.x;
  const double sample_s = seconds_since(sampling);
  EXPECT_TRUE(std::isfinite(sum));
  // Generous bounds for a loaded 2-core machine; the old code needed seconds per single sample.
  EXPECT_LT(prepare_s, 10.0);
  EXPECT_LT(sample_s, 1.0) << "200 samples took " << sample_s << " s: table rebuilt per sample?";
}

// The table is a pure function of the keys: copies share it and agree with an unprepared path.
TEST(CameraPathCost, PreparedAndUnpreparedPathsAgreeBitForBit) {
  CameraPath prepared = long_path(50);
  prepared.prepare();
  const CameraPath copy = prepared;
  const CameraPath unprepared = long_path(50);
  for (double t : {0.0, 0.3, 7.25, 24.5, 48.99, 49.0}) {
    const CameraPose a = prepared.sample(t, {}), b = unprepared.sample(t, {}),
                     c = copy.sample(t, {});
    EXPECT_EQ(a.position, b.position) << t;
    EXPECT_EQ(a.target, b.target) << t;
    EXPECT_EQ(a.position, c.position) << t;
  }
}

}  // namespace
}  // namespace sdfreel
