#pragma once
// Progress on stderr: a redrawn bar on a terminal, else one parseable line per frame
// ("frame 12/360 done in 1.84 s") for render-farm managers.
#include <chrono>

namespace sdfreel {

class Progress {
 public:
  explicit Progress(int total);
  void frame_done(int frame_index, double seconds, bool kept = false);
  void finish();

 private:
  int total_, done_ = 0;
  bool tty_;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace sdfreel
