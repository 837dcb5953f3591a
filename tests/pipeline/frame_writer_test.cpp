// The writer thread: frame order, a bounded queue, and the first failure stops it.
#include "pipeline/frame_writer.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <future>
#include <stdexcept>
#include <vector>

namespace sdfreel {
namespace {

TEST(FrameWriter, RunsJobsInTheOrderTheyCame) {
  std::vector<int> done;
  FrameWriter writer(2);
  for (int i = 0; i < 50; ++i) writer.push([&done, i] { done.push_back(i); });
  writer.finish();
  ASSERT_EQ(done.size(), 50u);
  for (int i = 0; i < 50; ++i) EXPECT_EQ(done[i], i);
}

TEST(FrameWriter, AFullQueueMakesTheRendererWait) {
  std::promise<void> release;
  std::shared_future<void> gate = release.get_future().share();
  std::atomic<int> done{0};
  FrameWriter writer(2);
  // One job being written plus two waiting fill the queue.
  for (int i = 0; i < 3; ++i)
    writer.push([gate, &done] {
      gate.wait();
      ++done;
    });
  auto fourth = std::async(std::launch::async, [&] { writer.push([&done] { ++done; }); });
  EXPECT_EQ(fourth.wait_for(std::chrono::milliseconds(200)), std::future_status::timeout);
  release.set_value();
  fourth.get();
  writer.finish();
  EXPECT_EQ(done.load(), 4);
}

TEST(FrameWriter, TheFirstFailureStopsTheWriterAndIsReported) {
  std::vector<int> done;
  FrameWriter writer(8);
  std::promise<void> release;
  std::shared_future<void> gate = release.get_future().share();
  writer.push([gate] { gate.wait(); });
  writer.push([&done] { done.push_back(1); });
  writer.push([] { throw std::runtime_error("frame 2: disk full"); });
  writer.push([&done] { done.push_back(3); });  // queued behind the failure: never runs
  release.set_value();
  try {
    writer.finish();
    FAIL() << "finish() did not rethrow";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "frame 2: disk full");
  }
  EXPECT_EQ(done, std::vector<int>{1});
}

TEST(FrameWriter, PushAfterAFailureRethrowsIt) {
  FrameWriter writer(1);
  writer.push([] { throw std::runtime_error("frame 0: cannot write"); });
  bool thrown = false;
  for (int i = 0; i < 100 && !thrown; ++i) {  // the writer fails soon; push sees it then
    try {
      writer.push([] {});
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    } catch (const std::runtime_error&) {
      thrown = true;
    }
  }
  EXPECT_TRUE(thrown);
  writer.finish_quietly();
}

TEST(FrameWriter, FinishQuietlyStillWritesWhatWasRendered) {
  std::atomic<int> done{0};
  {
    FrameWriter writer(4);
    for (int i = 0; i < 4; ++i) writer.push([&done] { ++done; });
    writer.finish_quietly();  // the renderer failed after these four frames
  }
  EXPECT_EQ(done.load(), 4);
}

}  // namespace
}  // namespace sdfreel
