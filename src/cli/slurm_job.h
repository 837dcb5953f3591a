#pragma once
// `sdfreel slurm` options, checked and turned into the job its scripts describe.
#include <string>
#include <vector>

#include "cli/slurm_scripts.h"

namespace sdfreel {

struct SlurmOptions {
  std::string timeline_path, out, partition, time;
  std::string backend, resolution, quality;  // render overrides, passed on to every task
  int tasks = 0, samples = 0, cpus_per_task = 0;
  std::vector<std::string> sbatch_args;
  bool dry_run = false;
};

// Loads the timeline with the overrides and checks every option; throws InputError or UsageError
// (exit 2) before anything is written.
SlurmJob make_slurm_job(const SlurmOptions& o);

}  // namespace sdfreel
