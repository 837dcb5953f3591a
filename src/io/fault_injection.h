#pragma once
// Test hook for the fault-injection tests: SDFREEL_FAULT_AT=N makes the N-th file-system operation
// of the process (write, fsync, close or rename of an output file, counted from 1) fail with
// ENOSPC, as a full disk would. Unset (always, outside tests), it costs one load per operation.
namespace sdfreel {

// True when this operation must fail; sets errno to ENOSPC then.
bool inject_io_fault();

// For tests inside one process: the N-th operation from now fails (0: none), as
// SDFREEL_FAULT_AT=N does for a whole process.
void set_io_fault_at(long n);

// While one lives, this thread's operations are neither counted nor failed (cache files: not
// outputs of the render, and written only when the cache misses).
class FaultInjectionPause {
 public:
  FaultInjectionPause();
  ~FaultInjectionPause();
  FaultInjectionPause(const FaultInjectionPause&) = delete;
  FaultInjectionPause& operator=(const FaultInjectionPause&) = delete;
};

}  // namespace sdfreel
