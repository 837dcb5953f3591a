#include "cli/progress.h"

#include <unistd.h>

#include <cstdio>

namespace sdfreel {

Progress::Progress(int total)
    : total_(total), tty_(::isatty(STDERR_FILENO)), start_(std::chrono::steady_clock::now()) {}

void Progress::frame_done(int frame_index, double seconds, bool kept) {
  ++done_;
  if (!tty_) {
    // Counts frames of this job (done/total); the frame's own number follows for logs.
    if (kept)
      std::fprintf(stderr, "frame %d/%d kept (frame %05d on disk matches the manifest)\n", done_,
                   total_, frame_index);
    else
      std::fprintf(stderr, "frame %d/%d done in %.2f s (frame %05d)\n", done_, total_, seconds,
                   frame_index);
    std::fflush(stderr);
    return;
  }
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const double fps = elapsed > 0.0 ? done_ / elapsed : 0.0;
  const double eta = fps > 0.0 ? (total_ - done_) / fps : 0.0;
  const int width = 30, filled = total_ ? done_ * width / total_ : width;
  char bar[width + 1];
  for (int i = 0; i < width; ++i) bar[i] = i < filled ? '#' : '-';
  bar[width] = 0;
  std::fprintf(stderr, "\r[%s] %d/%d  %.2f frames/s  ETA %02d:%02d ", bar, done_, total_, fps,
               int(eta) / 60, int(eta) % 60);
  std::fflush(stderr);
}

void Progress::finish() {
  if (tty_) std::fprintf(stderr, "\n");
}

}  // namespace sdfreel
