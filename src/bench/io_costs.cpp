#include "bench/io_costs.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <stdexcept>

#include "io/frame_files.h"

extern char** environ;

namespace sdfreel::bench {

namespace {

double median_of(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

double seconds_of(const timeval& t) {
  return double(t.tv_sec) + 1e-6 * double(t.tv_usec);
}

// One run of `argv`: wall seconds and CPU seconds of the child (wait4's rusage).
StartupTime run_timed(const std::vector<std::string>& argv) {
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
  const auto start = std::chrono::steady_clock::now();
  pid_t pid = 0;
  const int err = posix_spawn(&pid, args[0], &actions, nullptr, args.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (err != 0) throw std::runtime_error("cannot start " + argv[0]);
  int status = 0;
  rusage usage{};
  while (wait4(pid, &status, 0, &usage) < 0)
    if (errno != EINTR) throw std::runtime_error("cannot wait for " + argv[0]);
  StartupTime t;
  t.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  t.cpu_seconds = seconds_of(usage.ru_utime) + seconds_of(usage.ru_stime);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw std::runtime_error("the start-up still failed (" + argv[0] + " still " + argv[2] + ")");
  return t;
}

}  // namespace

StartupTime measure_startup(const std::string& exe, const std::string& timeline,
                            const std::string& backend, int repetitions,
                            const std::string& folder) {
  const std::vector<std::string> argv = {exe,
                                         "still",
                                         timeline,
                                         "--time",
                                         "0",
                                         "--resolution",
                                         STARTUP_RESOLUTION,
                                         "--backend",
                                         backend,
                                         "-o",
                                         folder + "/startup.png"};
  run_timed(argv);  // fills the cache folder (generated textures) for this build
  std::vector<double> wall, cpu;
  for (int i = 0; i < repetitions; ++i) {
    const StartupTime t = run_timed(argv);
    wall.push_back(t.wall_seconds);
    cpu.push_back(t.cpu_seconds);
  }
  return {median_of(wall), median_of(cpu)};
}

double time_frame_write(const ImageRGBA& linear, const ImageRGB16& display,
                        const std::string& folder) {
  const auto start = std::chrono::steady_clock::now();
  write_exr_atomic(folder + "/write-test.exr", linear, {{"bench", "write time"}});
  write_png16_atomic(folder + "/write-test.png", display);
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::string format_io_table(const std::vector<IoRow>& rows) {
  std::string out =
      "| scene | backend | start-up s (wall) | start-up CPU s | render s/frame | write s/frame "
      "(PNG + EXR) |\n| --- | --- | ---: | ---: | ---: | ---: |\n";
  for (const IoRow& r : rows) {
    char line[512];
    std::snprintf(line, sizeof line, "| %s | %s | %.3f | %.3f | %.4f | %.4f |\n", r.scene.c_str(),
                  r.backend.c_str(), r.startup.wall_seconds, r.startup.cpu_seconds,
                  r.render_seconds, r.write_seconds);
    out += line;
  }
  return out;
}

}  // namespace sdfreel::bench
