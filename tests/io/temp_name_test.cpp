// Temporary names carry host and PID (issue 17): start-up cleanup removes only this host's
// temporaries of dead processes, never another node's on shared storage.
#include "io/temp_name.h"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "io/atomic_file.h"

namespace sdfreel {
namespace {

namespace fs = std::filesystem;

// A PID that ran on this host and no longer does: a child that exited and was reaped.
long dead_pid() {
  const pid_t child = ::fork();
  if (child == 0) ::_exit(0);
  ::waitpid(child, nullptr, 0);
  return child;
}

TEST(TempName, NamesHostAndProcessAndReadsThemBack) {
  const std::string temp = temp_path_for("some/dir/00007.png");
  const std::string name = fs::path(temp).filename().string();
  EXPECT_EQ(name.rfind(".00007.png.tmp-" + temp_host_name() + "-", 0), 0u) << name;
  EXPECT_NE(temp_path_for("some/dir/00007.png"), temp) << "two calls share a name";
  const TempName t = parse_temp_name(name);
  ASSERT_TRUE(t.valid) << name;
  EXPECT_EQ(t.host, temp_host_name());
  EXPECT_EQ(t.pid, long(::getpid()));
}

TEST(TempName, HostNamesWithDashesAndOtherFilesAreToldApart) {
  const TempName t = parse_temp_name(".t.mkv.tmp-node-07.cluster-4242-3");
  ASSERT_TRUE(t.valid);
  EXPECT_EQ(t.host, "node-07.cluster");
  EXPECT_EQ(t.pid, 4242);
  for (const char* other :
       {"00001.png", ".t.mkv.tmp-4242-3", ".t.mkv.tmp--4242-3", ".t.mkv.tmp-node-x-3",
        ".t.mkv.tmp-node-4242-", "t.mkv.tmp-h-1-2", ".t.mkv.tmp-node-0-3"})
    EXPECT_FALSE(parse_temp_name(other).valid) << other;
}

TEST(TempName, CleanupRemovesOnlyThisHostsTemporariesOfDeadProcesses) {
  const fs::path dir =
      fs::temp_directory_path() / ("sdfreel-temp-name-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string dead = std::to_string(dead_pid()), live = std::to_string(::getpid());
  const std::string here = temp_host_name();
  const std::string mine_dead = ".00001.png.tmp-" + here + "-" + dead + "-0";
  const std::vector<std::string> kept = {
      ".00002.png.tmp-" + here + "-" + live + "-1",        // a live writer on this host
      ".00003.png.tmp-other-" + here + "-" + dead + "-2",  // another node, same PID dead here
      ".00004.png.tmp-other-node-" + live + "-3",          // another node, PID alive here
      "00005.png", ".00006.png.tmp-" + dead + "-4"};       // not a temporary of this format
  for (const std::string& n : kept) std::ofstream(dir / n) << "x";
  std::ofstream(dir / mine_dead) << "x";
  EXPECT_EQ(remove_stale_temp_files(dir.string()), 1);
  EXPECT_FALSE(fs::exists(dir / mine_dead));
  for (const std::string& n : kept) EXPECT_TRUE(fs::exists(dir / n)) << n << " was removed";
  fs::remove_all(dir);
}

}  // namespace
}  // namespace sdfreel
