#include "pipeline/frame_writer.h"

#include <chrono>

namespace sdfreel {

FrameWriter::FrameWriter(int capacity)
    : capacity_(size_t(capacity > 0 ? capacity : 1)), thread_([this] { run(); }) {}

FrameWriter::~FrameWriter() {
  finish_quietly();
}

void FrameWriter::run() {
  std::unique_lock<std::mutex> lock(mutex_);
  for (;;) {
    changed_.wait(lock, [this] { return closing_ || !jobs_.empty(); });
    if (jobs_.empty()) return;  // closing and drained
    std::function<void()> job = std::move(jobs_.front());
    lock.unlock();
    const auto start = std::chrono::steady_clock::now();
    std::exception_ptr failed;
    try {
      job();
    } catch (...) {
      failed = std::current_exception();
    }
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    lock.lock();
    busy_seconds_ += seconds;
    jobs_.pop_front();  // popped only now: a job being written still counts against capacity
    if (failed && !error_) {
      error_ = failed;
      jobs_.clear();  // nothing after a failed frame is published
    }
    changed_.notify_all();
    if (error_) {
      changed_.wait(lock, [this] { return closing_; });
      return;
    }
  }
}

void FrameWriter::push(std::function<void()> job) {
  std::unique_lock<std::mutex> lock(mutex_);
  changed_.wait(lock, [this] { return error_ || jobs_.size() <= capacity_; });
  if (error_) std::rethrow_exception(error_);
  jobs_.push_back(std::move(job));
  changed_.notify_all();
}

void FrameWriter::stop_and_join() noexcept {
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    closing_ = true;
  }
  changed_.notify_all();
  if (thread_.joinable()) thread_.join();
}

void FrameWriter::finish() {
  stop_and_join();
  if (error_) std::rethrow_exception(error_);
}

void FrameWriter::finish_quietly() noexcept {
  stop_and_join();
}

}  // namespace sdfreel
