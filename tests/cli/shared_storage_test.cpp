// Issue 17: on storage shared by several nodes, a starting render removes only its own host's
// temporaries of dead processes. Another node's temporary (its PID means nothing here, even when
// no such process runs on this host) is the frame that node is writing: it must survive.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>

#include "cli/harness.h"
#include "io/temp_name.h"

namespace sdfreel::test {
namespace {

namespace fs = std::filesystem;

std::string dead_pid() {
  const pid_t child = ::fork();
  if (child == 0) ::_exit(0);
  ::waitpid(child, nullptr, 0);
  return std::to_string(child);
}

TEST(SharedStorage, RenderCleansOnlyItsOwnHostsStaleTemporaries) {
  const std::string dir = scratch_dir("shared-storage-temps");
  write_file(dir + "/t.toml", small_timeline(4));
  fs::create_directories(dir + "/out/frames");
  const std::string pid = dead_pid();
  const std::string other_node =
      "frames/.00003.png.tmp-other-" + temp_host_name() + "-" + pid + "-0";
  const std::string killed_here = "frames/.00002.png.tmp-" + temp_host_name() + "-" + pid + "-1";
  const std::string killed_video = ".small.mkv.tmp-" + temp_host_name() + "-" + pid + "-2";
  for (const std::string& n : {other_node, killed_here, killed_video})
    write_file(dir + "/out/" + n, "partial");
  const RunResult r = run_sdfreel("render t.toml --no-video --frames 0-1", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(fs::exists(dir + "/out/" + other_node)) << "another node's temporary was removed";
  EXPECT_FALSE(fs::exists(dir + "/out/" + killed_here));
  EXPECT_FALSE(fs::exists(dir + "/out/" + killed_video));
}

}  // namespace
}  // namespace sdfreel::test
