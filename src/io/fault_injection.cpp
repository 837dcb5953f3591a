#include "io/fault_injection.h"

#include <atomic>
#include <cerrno>
#include <cstdlib>

namespace sdfreel {
namespace {

std::atomic<long>& fault_at() {
  static std::atomic<long> at{[] {
    const char* v = std::getenv("SDFREEL_FAULT_AT");
    return v ? std::atol(v) : 0L;
  }()};
  return at;
}

std::atomic<long> g_operations{0};
thread_local int t_paused = 0;

}  // namespace

bool inject_io_fault() {
  const long at = fault_at().load(std::memory_order_relaxed);
  if (at <= 0 || t_paused > 0 || g_operations.fetch_add(1) + 1 != at) return false;
  errno = ENOSPC;
  return true;
}

void set_io_fault_at(long n) {
  g_operations = 0;
  fault_at() = n;
}

FaultInjectionPause::FaultInjectionPause() {
  ++t_paused;
}

FaultInjectionPause::~FaultInjectionPause() {
  --t_paused;
}

}  // namespace sdfreel
