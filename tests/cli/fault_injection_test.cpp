// Fault injection (issue 17): a disk that fills up, a write failing at every write site, kill -9 at
// many points of a render with video, concurrent writers. Each ends in check_output_folder: every
// listed frame complete and matching its hash, nothing torn published, exit code as documented.
#include <gtest/gtest.h>
#include <sys/mount.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <random>
#include <regex>

#include "cli/folder_check.h"
#include "cli/harness.h"

namespace sdfreel::test {
namespace {

namespace fs = std::filesystem;

// A size-limited tmpfs at `path` while in scope; mounted() is false where mounting is not allowed
// (not root, or a container without CAP_SYS_ADMIN).
class SmallDisk {
 public:
  SmallDisk(const std::string& path, const std::string& size) : path_(path) {
    fs::create_directories(path);
    mounted_ = ::mount("tmpfs", path.c_str(), "tmpfs", 0, ("size=" + size).c_str()) == 0;
  }
  ~SmallDisk() {
    if (mounted_) ::umount2(path_.c_str(), MNT_DETACH);
  }
  bool mounted() const { return mounted_; }

 private:
  std::string path_;
  bool mounted_ = false;
};

TEST(FaultInjection, FullDiskNeverPublishesATruncatedFrameAndExitsOne) {
  const std::string dir = scratch_dir("fault-tmpfs");
  SmallDisk disk(dir + "/disk", "60k");
  if (!disk.mounted()) GTEST_SKIP() << "cannot mount a tmpfs here (needs root)";
  // About 15 KB of frame files a frame: the disk fills during frame 2 or 3.
  write_file(dir + "/disk/t.toml", small_timeline(8));
  RunResult r = run_sdfreel("render t.toml --no-video", dir + "/disk");
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_NE(r.err.find("No space left"), std::string::npos) << r.err;
  EXPECT_TRUE(std::regex_search(r.err, std::regex("error: frame [0-9]+: "))) << r.err;
  FolderReport rep = check_output_folder(dir + "/disk/out", "");
  EXPECT_TRUE(rep.problems.empty()) << rep.describe();
  EXPECT_LT(rep.listed, 8);
}

TEST(FaultInjection, RerenderOnANearlyFullDiskFailsAndKeepsTheOldFrames) {
  const std::string dir = scratch_dir("fault-tmpfs-rerender");
  SmallDisk disk(dir + "/disk", "400k");
  if (!disk.mounted()) GTEST_SKIP() << "cannot mount a tmpfs here (needs root)";
  write_file(dir + "/disk/t.toml", small_timeline(4));
  ASSERT_EQ(run_sdfreel("render t.toml --no-video", dir + "/disk").status, 0);
  // Fill the disk, then give back one 4 KB page: less than a frame file (each is 7-9 KB).
  run("dd if=/dev/zero of=filler bs=4k 2>/dev/null; truncate -s -4k filler", dir + "/disk");
  const RunResult r = run_sdfreel("render t.toml --no-video", dir + "/disk");
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_NE(r.err.find("frame "), std::string::npos) << r.err;
  fs::remove(dir + "/disk/filler");
  const FolderReport rep = check_output_folder(dir + "/disk/out", "");
  EXPECT_TRUE(rep.problems.empty()) << rep.describe();
  EXPECT_EQ(rep.listed, 4);
  EXPECT_EQ(run_sdfreel("encode out -o v.mkv --codec ffv1", dir + "/disk").status, 0);
}

// SDFREEL_FAULT_AT=N fails the N-th write, fsync, close or rename of the process with ENOSPC. Every
// N until the render gets through: each run exits 1 saying so and leaves a consistent folder with
// no temporaries; a --resume afterwards (tried after every third fault) completes it.
TEST(FaultInjection, WriteFailureAtEveryWriteSite) {
  const std::string dir = scratch_dir("fault-every-site");
  write_file(dir + "/t.toml", small_timeline(2));
  int n = 1;
  for (; n < 400; ++n) {
    fs::remove_all(dir + "/out");
    const RunResult r = run(
        "SDFREEL_FAULT_AT=" + std::to_string(n) + " '" + sdfreel_binary() + "' render t.toml", dir);
    if (r.status == 0) break;  // n is past the last operation: nothing failed
    EXPECT_EQ(r.status, 1) << "fault " << n << ": " << r.err;
    EXPECT_NE(r.err.find("No space left on device"), std::string::npos) << "fault " << n << r.err;
    const FolderReport rep = check_output_folder(dir + "/out", "small.mkv");
    EXPECT_TRUE(rep.problems.empty()) << "fault " << n << ": " << r.err << rep.describe();
    if (n % 3 != 0) continue;  // a resume after every third fault keeps the test under a minute
    const RunResult resumed = run_sdfreel("render t.toml --resume", dir);
    EXPECT_EQ(resumed.status, 0) << "fault " << n << ": " << resumed.err;
    const FolderReport done = check_output_folder(dir + "/out", "small.mkv");
    EXPECT_TRUE(done.problems.empty()) << "fault " << n << " then resume:\n" << done.describe();
    EXPECT_EQ(done.listed, 2) << "fault " << n;
    EXPECT_TRUE(done.has_video) << "fault " << n;
  }
  // Frames, journal, manifest, framemd5 and video each take several operations.
  EXPECT_GT(n, 30) << "too few injected faults: is SDFREEL_FAULT_AT honoured?";
  std::printf("injected a fault at each of %d operations\n", n - 1);
}

// kill -9 at many moments of a render with video (start-up, frames, video finish), each followed
// by --resume: the result is always the complete render, with no temporaries left.
TEST(FaultInjection, KillAtManyPointsThenResume) {
  const std::string dir = scratch_dir("fault-kill");
  write_file(dir + "/t.toml", small_timeline(10));
  const auto start = std::chrono::steady_clock::now();
  ASSERT_EQ(run_sdfreel("render t.toml", dir).status, 0);
  const double full =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const std::string want = read_file(dir + "/out/frames.framemd5");
  // Spread over the first 80% of a full run's time (start-up, frames, video finish) plus a seeded
  // jitter, printed for reproduction.
  const unsigned seed = unsigned(std::chrono::system_clock::now().time_since_epoch().count());
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> jitter(0.0, 1.0);
  constexpr int kPoints = 12;
  int killed_mid_run = 0;
  for (int k = 0; k < kPoints; ++k) {
    fs::remove_all(dir + "/out");
    const double delay = 0.8 * full * (k + jitter(rng)) / kPoints;
    char cmd[512];
    std::snprintf(cmd, sizeof cmd,
                  "'%s' render t.toml 2>/dev/null & pid=$!; sleep %.3f; "
                  "kill -9 $pid 2>/dev/null; wait $pid; echo $?",
                  sdfreel_binary().c_str(), delay);
    const RunResult killed = run(cmd, dir);
    if (killed.out == "137\n") ++killed_mid_run;
    const std::string context =
        "kill at " + std::to_string(delay) + " s (seed " + std::to_string(seed) + ")";
    // What a kill leaves is consistent except for temporaries of the killed writer.
    const FolderReport after_kill = check_output_folder(dir + "/out", "small.mkv", true);
    EXPECT_TRUE(after_kill.problems.empty()) << context << "\n" << after_kill.describe();
    const RunResult r = run_sdfreel("render t.toml --resume", dir);
    ASSERT_EQ(r.status, 0) << context << ": " << r.err;
    const FolderReport rep = check_output_folder(dir + "/out", "small.mkv");
    EXPECT_TRUE(rep.problems.empty()) << context << "\n" << rep.describe();
    EXPECT_EQ(rep.listed, 10) << context;
    EXPECT_TRUE(rep.has_video) << context;
    EXPECT_EQ(read_file(dir + "/out/frames.framemd5"), want) << context;
  }
  EXPECT_GE(killed_mid_run, kPoints / 3) << "most kills should land before the render ends";
}

// Concurrent writers into one folder: three shards and a whole render at once, then encode.
TEST(FaultInjection, ConcurrentShardsAndRenderIntoOneFolder) {
  const std::string dir = scratch_dir("fault-concurrent");
  write_file(dir + "/t.toml", small_timeline(9));
  const std::string bin = "'" + sdfreel_binary() + "' ";
  const RunResult r = run(bin + "render t.toml --shard 0/3 2>e0 & a=$!; " + bin +
                              "render t.toml --shard 1/3 2>e1 & b=$!; " + bin +
                              "render t.toml --shard 2/3 2>e2 & c=$!; " + bin +
                              "render t.toml 2>e3 & d=$!; wait $a; echo $?; wait $b; echo $?; "
                              "wait $c; echo $?; wait $d; echo $?",
                          dir);
  EXPECT_EQ(r.out, "0\n0\n0\n0\n") << read_file(dir + "/e0") << read_file(dir + "/e3");
  const FolderReport rep = check_output_folder(dir + "/out", "small.mkv");
  EXPECT_TRUE(rep.problems.empty()) << rep.describe();
  EXPECT_EQ(rep.listed, 9);
  EXPECT_TRUE(rep.has_video);
  const RunResult enc = run_sdfreel("encode out -o joined.mkv --codec ffv1", dir);
  EXPECT_EQ(enc.status, 0) << enc.err;
  EXPECT_EQ(read_file(dir + "/joined.mkv"), read_file(dir + "/out/small.mkv"));
}

}  // namespace
}  // namespace sdfreel::test
