#pragma once
// Frame files, journal lines and video frames are written on one thread of their own, in the
// order they were queued, while the next frame renders: a run is bound by rendering, not by PNG
// compression and fsync. The queue is bounded (a full queue makes the renderer wait), so memory
// stays at a few frames. The first failure stops the writer (later jobs are dropped, so nothing
// is listed after a frame that was not written) and is rethrown to the renderer.
#include <condition_variable>
#include <deque>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>

namespace sdfreel {

class FrameWriter {
 public:
  // `capacity`: jobs that may wait behind the one being written.
  explicit FrameWriter(int capacity = 2);
  ~FrameWriter();  // drains like finish_quietly()
  FrameWriter(const FrameWriter&) = delete;
  FrameWriter& operator=(const FrameWriter&) = delete;

  // Queues `job`; waits while the queue is full. Rethrows a failure of an earlier job.
  void push(std::function<void()> job);
  // Waits until every queued job is done and the thread has ended; rethrows the first failure.
  void finish();
  // The same without throwing (the renderer failed: publish what was rendered, then report).
  void finish_quietly() noexcept;
  // Seconds the writer spent in jobs so far (read after finish()).
  double busy_seconds() const { return busy_seconds_; }

 private:
  void run();
  void stop_and_join() noexcept;

  const size_t capacity_;
  std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<std::function<void()>> jobs_;
  std::exception_ptr error_;
  bool closing_ = false;
  double busy_seconds_ = 0.0;
  std::thread thread_;
};

}  // namespace sdfreel
