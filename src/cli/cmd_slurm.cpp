// `sdfreel slurm TIMELINE --tasks N`: renders a timeline on a Slurm cluster (docs/farm.md): a job
// array with one shard per task, then an encode job that waits for every task to succeed.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>

#include "cli/commands_impl.h"
#include "cli/slurm_job.h"
#include "cli/subprocess.h"
#include "io/atomic_file.h"

namespace sdfreel {

namespace fs = std::filesystem;

namespace {

// Checked like every other file (io/atomic_file.h); sbatch reads the script, so the mode bits are
// only for running it by hand.
void write_script(const std::string& path, const std::string& text) {
  try {
    write_file_atomic(path, text);
  } catch (const std::runtime_error& e) {
    throw RenderError(e.what());
  }
  fs::permissions(path, fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec |
                            fs::perms::others_read | fs::perms::others_exec);
}

// `sbatch --parsable ...` prints "JOBID" or "JOBID;CLUSTER". Returns "" on failure.
std::string submit(const std::vector<std::string>& argv) {
  const ProgramResult r = run_program(argv);
  std::string id;
  for (char c : r.out) {
    if (c < '0' || c > '9') break;
    id += c;
  }
  if (r.status != 0 || id.empty()) {
    std::fprintf(stderr, "sdfreel: error: sbatch failed (exit %d) for %s\n", r.status,
                 argv.back().c_str());
    return "";
  }
  return id;
}

int print_dry_run(const SlurmJob& job) {
  std::printf("# ---- %s\n%s", render_script_path(job).c_str(), render_script(job).c_str());
  if (!job.video.empty())
    std::printf("# ---- %s\n%s", encode_script_path(job).c_str(), encode_script(job).c_str());
  std::printf("# ---- submit with\nsbatch --parsable %s\n", render_script_path(job).c_str());
  if (!job.video.empty())
    std::printf("sbatch --parsable --dependency=afterok:ARRAY_JOB_ID %s\n",
                encode_script_path(job).c_str());
  return 0;
}

int run_slurm(const SlurmOptions& o) {
  const SlurmJob job = make_slurm_job(o);
  if (o.dry_run) return print_dry_run(job);
  if (!on_path("sbatch"))
    throw RenderError("sbatch is not on PATH: run this on a Slurm submit host, or use --dry-run");

  // Slurm opens the logs but does not create their folder.
  fs::create_directories(logs_dir(job));
  fs::create_directories(slurm_dir(job));
  write_script(render_script_path(job), render_script(job));
  if (!job.video.empty()) write_script(encode_script_path(job), encode_script(job));

  const std::string array_id = submit({"sbatch", "--parsable", render_script_path(job)});
  if (array_id.empty()) return 1;
  std::printf("array_job=%s\n", array_id.c_str());
  std::fflush(stdout);
  std::fprintf(stderr, "sdfreel: job array %s: %d render tasks, logs in %s/task-N.log\n",
               array_id.c_str(), job.tasks, logs_dir(job).c_str());
  if (job.video.empty()) return 0;
  const std::string encode_id =
      submit({"sbatch", "--parsable", "--dependency=afterok:" + array_id, encode_script_path(job)});
  if (encode_id.empty()) {
    std::fprintf(stderr,
                 "sdfreel: the render tasks run; encode later with `sdfreel encode %s -o %s/%s`\n",
                 job.out_dir.c_str(), job.out_dir.c_str(), job.video.c_str());
    return 1;
  }
  std::printf("encode_job=%s\n", encode_id.c_str());
  std::fprintf(stderr, "sdfreel: encode job %s writes %s/%s once every task succeeded\n",
               encode_id.c_str(), job.out_dir.c_str(), job.video.c_str());
  return 0;
}

}  // namespace

void add_slurm_command(CLI::App& app, int& status) {
  auto o = std::make_shared<SlurmOptions>();
  CLI::App* cmd = app.add_subcommand(
      "slurm", "render a timeline on a Slurm cluster: a job array of shards, then the encode");
  cmd->add_option("TIMELINE", o->timeline_path, "timeline file (TOML)")->required();
  cmd->add_option("--tasks", o->tasks, "array tasks, one contiguous shard of the frames each")
      ->required()
      ->check(CLI::Range(1, 1000000));
  cmd->add_option("--partition", o->partition, "Slurm partition (default: the cluster's)");
  cmd->add_option("--time", o->time, "time limit per job, e.g. 30, 2:00:00, 1-00:00:00");
  cmd->add_option("--cpus-per-task", o->cpus_per_task, "CPUs per task, also the render's --threads")
      ->check(CLI::Range(1, 1024));
  cmd->add_option("--sbatch-arg", o->sbatch_args,
                  "extra sbatch option for both jobs, e.g. --sbatch-arg=--account=vfx (repeatable)")
      ->allow_extra_args(false);
  cmd->add_option("--backend", o->backend, "cpu | gl | egl | osmesa (GL device: SDFREEL_GL_DEVICE)")
      ->check(CLI::IsMember(backend_names()));
  cmd->add_option("--resolution", o->resolution, "WxH, overrides the timeline");
  cmd->add_option("--samples", o->samples, "samples per pixel, 1..1024")
      ->check(CLI::Range(1, 1024));
  cmd->add_option("--quality", o->quality, "draft | final | reference")
      ->check(CLI::IsMember({"draft", "final", "reference"}));
  cmd->add_option("--out", o->out, "output folder on shared storage, overrides [output] dir");
  cmd->add_flag("--dry-run", o->dry_run, "print the scripts and sbatch commands; write nothing");
  cmd->callback([o, &status] { status = run_slurm(*o); });
}

}  // namespace sdfreel
