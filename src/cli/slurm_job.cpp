#include "cli/slurm_job.h"

#include <cctype>
#include <filesystem>
#include <regex>

#include "cli/render_options.h"
#include "pipeline/errors.h"
#include "timeline/video_codec_rules.h"

namespace sdfreel {

namespace fs = std::filesystem;

namespace {

// Slurm's time limits: minutes, MM:SS, HH:MM:SS, D-HH, D-HH:MM, D-HH:MM:SS, or no limit.
bool is_slurm_time(const std::string& t) {
  static const std::regex form(R"(\d+(:\d+){0,2}|\d+-\d+(:\d+){0,2}|UNLIMITED|INFINITE)");
  return std::regex_match(t, form);
}

// The folder appears unquoted in #SBATCH --output, where sbatch splits on blanks and expands %.
void check_out_dir(const std::string& dir) {
  for (unsigned char c : dir)
    if (c <= ' ' || c == '%' || c == '\'' || c == '"' || c == '\\' || c == 127)
      throw UsageError("output folder '" + dir +
                       "': Slurm log paths cannot hold blanks, quotes, backslashes or %; choose "
                       "another --out");
}

void check_sbatch_arg(const std::string& a) {
  if (a.size() < 2 || a[0] != '-')
    throw UsageError("--sbatch-arg '" + a +
                     "': expected an sbatch option, e.g. --sbatch-arg=--qos=high");
  for (unsigned char c : a)
    if (c < ' ' || c == 127) throw UsageError("--sbatch-arg: control characters are not allowed");
}

std::string job_name(const std::string& timeline_path) {
  std::string name = fs::path(timeline_path).stem().string();
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_' && c != '.') c = '_';
  return name.empty() ? "timeline" : name;
}

}  // namespace

SlurmJob make_slurm_job(const SlurmOptions& o) {
  RenderOptions ro;
  ro.timeline_path = o.timeline_path;
  ro.backend = o.backend;
  ro.resolution = o.resolution;
  ro.samples = o.samples;
  ro.quality = o.quality;
  ro.out = o.out;
  const Timeline tl = load_with_overrides(ro);

  if (o.tasks < 1 || o.tasks > tl.frame_count())
    throw UsageError("--tasks " + std::to_string(o.tasks) + ": expected 1.." +
                     std::to_string(tl.frame_count()) + " (one task renders at least one frame)");
  static const std::regex partition_form(R"([A-Za-z0-9_.,-]+)");
  if (!o.partition.empty() && !std::regex_match(o.partition, partition_form))
    throw UsageError("--partition '" + o.partition + "': expected a partition name (or a,b)");
  if (!o.time.empty() && !is_slurm_time(o.time))
    throw UsageError("--time '" + o.time +
                     "': expected minutes, MM:SS, HH:MM:SS, D-HH, D-HH:MM or D-HH:MM:SS");
  for (const std::string& a : o.sbatch_args) check_sbatch_arg(a);

  SlurmJob job;
  std::error_code ec;
  job.sdfreel = fs::canonical("/proc/self/exe", ec).string();
  if (ec) throw RenderError("cannot find this executable's path (/proc/self/exe)");
  job.timeline = fs::absolute(o.timeline_path).lexically_normal().string();
  job.out_dir = fs::absolute(tl.out_dir).lexically_normal().string();
  while (job.out_dir.size() > 1 && job.out_dir.back() == '/') job.out_dir.pop_back();
  check_out_dir(job.out_dir);
  job.name = job_name(o.timeline_path);
  job.video = tl.video;
  job.tasks = o.tasks;
  job.partition = o.partition;
  job.time = o.time;
  job.cpus_per_task = o.cpus_per_task;
  job.sbatch_args = o.sbatch_args;
  if (!o.backend.empty()) job.render_args.insert(job.render_args.end(), {"--backend", o.backend});
  if (!o.resolution.empty())
    job.render_args.insert(job.render_args.end(), {"--resolution", o.resolution});
  if (o.samples)
    job.render_args.insert(job.render_args.end(), {"--samples", std::to_string(o.samples)});
  if (!o.quality.empty()) job.render_args.insert(job.render_args.end(), {"--quality", o.quality});
  // The timeline's codec and quality: encode would take the codec from the container.
  job.encode_args = {"--codec", tl.codec};
  if (const VideoCodecRule* rule = find_video_codec_rule(tl.codec); rule && rule->takes_crf)
    job.encode_args.insert(job.encode_args.end(), {"--crf", std::to_string(tl.crf)});
  return job;
}

}  // namespace sdfreel
