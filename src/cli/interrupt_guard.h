#pragma once
// SIGINT and SIGTERM during a render. The first one asks the render to stop after the frame in
// hand, so that its finished frames are written and listed in manifest.json and no temporary file
// stays behind; a second one ends the process at once (the default action, as before).
namespace sdfreel {

class InterruptGuard {
 public:
  InterruptGuard();   // installs the handlers
  ~InterruptGuard();  // puts the previous ones back
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;
  // The signal received since construction (SIGINT or SIGTERM), 0 when none.
  static int signal_seen();
};

// "SIGINT", "SIGTERM".
const char* signal_name(int signo);

}  // namespace sdfreel
