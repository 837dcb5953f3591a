#pragma once
// Timing a whole process, as a user starting sdfreel sees it: wall seconds from spawn to exit and
// the CPU seconds of every thread of the child (wait4's rusage). Used by the bench's start-up
// still (bench/io_costs.h) and its whole-process renders (bench/whole_process.h).
#include <string>
#include <vector>

namespace sdfreel::bench {

struct ProcessTime {
  double wall_seconds = 0.0;
  double cpu_seconds = 0.0;  // user + system
};

// Runs argv (argv[0] a path; stderr to /dev/null) and times it. Throws std::runtime_error naming
// `what` if it cannot start or does not exit with status 0.
ProcessTime run_timed(const std::vector<std::string>& argv, const std::string& what);

}  // namespace sdfreel::bench
