#pragma once
// The batch scripts of `sdfreel slurm` (docs/farm.md): a job array that renders one shard per task
// into a shared output folder, and a job that encodes the video once every task succeeded.
#include <string>
#include <vector>

namespace sdfreel {

struct SlurmJob {
  std::string sdfreel;   // absolute path of the executable the nodes run
  std::string timeline;  // absolute
  std::string out_dir;   // absolute, shared by every task
  std::string name;      // job name suffix: the timeline's file stem
  std::string video;     // file name in out_dir; empty: no encode job
  int tasks = 1;
  std::string partition, time;  // empty: the cluster's defaults
  int cpus_per_task = 0;        // 0: the cluster's default; else also the render's --threads
  std::vector<std::string> render_args;  // already validated render overrides (--backend cpu, ...)
  std::vector<std::string> encode_args;  // e.g. the timeline's --crf
  std::vector<std::string> sbatch_args;  // extra #SBATCH lines for both jobs
};

// Where the scripts and logs go inside the output folder.
std::string slurm_dir(const SlurmJob& job);  // <out>/slurm
std::string logs_dir(const SlurmJob& job);   // <out>/logs
std::string render_script_path(const SlurmJob& job);
std::string encode_script_path(const SlurmJob& job);

// Task k runs `sdfreel render T --shard k/N --no-video --resume` into the output folder, so a
// requeued task renders only the frames its earlier run did not finish; its exit status is
// sdfreel's: 0 only when every frame of its shard is written.
std::string render_script(const SlurmJob& job);
// `sdfreel encode` of the output folder; submitted with --dependency=afterok:<array job>.
std::string encode_script(const SlurmJob& job);

// Single-quoted for /bin/sh.
std::string shell_quote(const std::string& s);

}  // namespace sdfreel
