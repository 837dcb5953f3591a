#include "cli/interrupt_guard.h"

#include <csignal>
#include <utility>

namespace sdfreel {
namespace {

volatile std::sig_atomic_t g_signal = 0;
struct sigaction g_previous_int, g_previous_term;

void on_signal(int signo) {
  g_signal = signo;
}

}  // namespace

InterruptGuard::InterruptGuard() {
  g_signal = 0;
  struct sigaction sa {};
  sa.sa_handler = on_signal;
  sigemptyset(&sa.sa_mask);
  sa.sa_flags = SA_RESETHAND;  // the second signal takes the default action: the process ends
  // A signal ignored when sdfreel started (nohup, a shell's background job) stays ignored.
  for (auto [signo, previous] : {std::pair{SIGINT, &g_previous_int}, {SIGTERM, &g_previous_term}}) {
    sigaction(signo, nullptr, previous);
    if (previous->sa_handler != SIG_IGN) sigaction(signo, &sa, nullptr);
  }
}

InterruptGuard::~InterruptGuard() {
  sigaction(SIGINT, &g_previous_int, nullptr);
  sigaction(SIGTERM, &g_previous_term, nullptr);
}

int InterruptGuard::signal_seen() {
  return g_signal;
}

const char* signal_name(int signo) {
  return signo == SIGINT ? "SIGINT" : signo == SIGTERM ? "SIGTERM" : "a signal";
}

}  // namespace sdfreel
