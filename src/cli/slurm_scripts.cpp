#include "cli/slurm_scripts.h"

namespace sdfreel {

namespace {

// The #SBATCH lines both jobs share, after their own.
std::string common_directives(const SlurmJob& job) {
  std::string s;
  if (!job.partition.empty()) s += "#SBATCH --partition=" + job.partition + "\n";
  if (!job.time.empty()) s += "#SBATCH --time=" + job.time + "\n";
  for (const std::string& a : job.sbatch_args) s += "#SBATCH " + a + "\n";
  return s;
}

// For comment lines: a control character (a newline in a file name) would end the comment.
std::string printable(std::string s) {
  for (char& c : s)
    if (static_cast<unsigned char>(c) < ' ' || c == 127) c = '?';
  return s;
}

}  // namespace

std::string slurm_dir(const SlurmJob& job) {
  return job.out_dir + "/slurm";
}
std::string logs_dir(const SlurmJob& job) {
  return job.out_dir + "/logs";
}
std::string render_script_path(const SlurmJob& job) {
  return slurm_dir(job) + "/render.sh";
}
std::string encode_script_path(const SlurmJob& job) {
  return slurm_dir(job) + "/encode.sh";
}

std::string shell_quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

std::string render_script(const SlurmJob& job) {
  const std::string n = std::to_string(job.tasks);
  std::string s = "#!/bin/sh\n";
  s += "# Written by `sdfreel slurm`: renders " + printable(job.timeline) +
       ", one shard per array task.\n";
  s += "#SBATCH --job-name=sdfreel-" + job.name + "\n";
  s += "#SBATCH --array=0-" + std::to_string(job.tasks - 1) + "\n";
  // One log per task; appended to, so a requeued task's log keeps the earlier attempt.
  s += "#SBATCH --output=" + logs_dir(job) + "/task-%a.log\n";
  s += "#SBATCH --open-mode=append\n";
  if (job.cpus_per_task) s += "#SBATCH --cpus-per-task=" + std::to_string(job.cpus_per_task) + "\n";
  s += common_directives(job);
  s += "echo \"sdfreel: task ${SLURM_ARRAY_TASK_ID}/" + n +
       " of job ${SLURM_ARRAY_JOB_ID} on ${SLURMD_NODENAME:-?}, restart ${SLURM_RESTART_COUNT:-0}, "
       "$(date -u +%Y-%m-%dT%H:%M:%SZ)\" >&2\n";
  s += "exec " + shell_quote(job.sdfreel) + " render " + shell_quote(job.timeline) + " --out " +
       shell_quote(job.out_dir) + " --shard \"${SLURM_ARRAY_TASK_ID}/" + n +
       "\" --no-video --resume";
  if (job.cpus_per_task) s += " --threads " + std::to_string(job.cpus_per_task);
  for (const std::string& a : job.render_args) s += " " + shell_quote(a);
  return s + "\n";
}

std::string encode_script(const SlurmJob& job) {
  std::string s = "#!/bin/sh\n";
  s += "# Written by `sdfreel slurm`: encodes " + printable(job.out_dir + "/" + job.video) +
       " once every render task succeeded.\n";
  s += "#SBATCH --job-name=sdfreel-" + job.name + "-encode\n";
  s += "#SBATCH --output=" + logs_dir(job) + "/encode.log\n";
  s += "#SBATCH --open-mode=append\n";
  s += common_directives(job);
  s += "exec " + shell_quote(job.sdfreel) + " encode " + shell_quote(job.out_dir) + " -o " +
       shell_quote(job.out_dir + "/" + job.video);
  for (const std::string& a : job.encode_args) s += " " + shell_quote(a);
  return s + "\n";
}

}  // namespace sdfreel
