// The fur exhibit's frames are pure functions of (timeline, frame index) on both backends: a frame
// rendered alone by a fresh backend has the same bits as the same frame rendered in sequence after
// the others, across a push (the physics is recomputed from the timeline, never carried over).
#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "backends/cpu/cpu_backend.h"
#include "backends/gl/gl_backend.h"
#include "pipeline/frame_pipeline.h"
#include "scenes/registry.h"
#include "timeline/timeline.h"

namespace sdfreel {
namespace {

std::unique_ptr<Backend> make_backend(const std::string& name) {
  if (name == "cpu") return std::make_unique<CpuBackend>(2);
  return std::make_unique<GlBackend>();
}

class FurFrames : public ::testing::TestWithParam<std::string> {};

TEST_P(FurFrames, AFrameAloneEqualsTheFrameInSequence) {
  const Timeline tl = load_timeline(
      all_scenes(), std::string(SDFREEL_SOURCE_DIR) + "/tests/golden/fur/small.toml", nullptr);
  std::unique_ptr<Backend> sequence_backend;
  try {
    sequence_backend = make_backend(GetParam());
  } catch (const std::exception& e) {
    GTEST_SKIP() << "backend unavailable: " << e.what();
  }
  FramePipeline sequence(tl, std::move(sequence_backend));
  std::vector<std::string> hashes;
  for (int i = 0; i < tl.frame_count(); ++i) hashes.push_back(sequence.render(i).linear_hash);
  ASSERT_GE(hashes.size(), 4u);
  EXPECT_NE(hashes[1], hashes[3]) << "the frames should move";
  for (int k : {tl.frame_count() - 1, 2}) {
    FramePipeline alone(tl, make_backend(GetParam()));
    EXPECT_EQ(alone.render(k).linear_hash, hashes[size_t(k)]) << "frame " << k;
  }
}

INSTANTIATE_TEST_SUITE_P(Backends, FurFrames, ::testing::Values("cpu", "gl"));

}  // namespace
}  // namespace sdfreel
