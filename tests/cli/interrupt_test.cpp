// Ctrl-C (SIGINT) and SIGTERM during a render: the frame in hand finishes, every finished frame is
// listed in manifest.json itself (not only in the journal), no temporary file stays behind, the
// exit status is 128 + the signal, the last line says how many frames are kept and that --resume
// renders the rest, and --resume then makes the same frames and the video.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "cli/folder_check.h"
#include "cli/harness.h"

namespace sdfreel::test {
namespace {

void interrupt_then_resume(const std::string& signal, const std::string& status) {
  const std::string dir = scratch_dir("interrupt-" + signal);
  // 16 samples a frame: slow enough that the signal lands long before the 300th frame.
  std::string timeline = small_timeline(300);
  timeline.replace(timeline.find("samples = 1"), 11, "samples = 16");
  write_file(dir + "/t.toml", timeline);
  const RunResult stopped =
      // env --default-signal: a shell starts background jobs with SIGINT ignored, which sdfreel
      // (like nohup's children) then keeps ignoring.
      run("env --default-signal=INT '" + sdfreel_binary() + "' render t.toml 2>err & pid=$!; " +
              "for i in $(seq 1000); do n=$(ls out/frames 2>/dev/null | grep -c 'png$'); " +
              "[ \"$n\" -ge 2 ] && break; sleep 0.02; done; kill -" + signal +
              " $pid; wait $pid; echo $?",
          dir);
  ASSERT_EQ(stopped.out, status + "\n") << read_file(dir + "/err");
  const std::string err = read_file(dir + "/err");
  EXPECT_NE(err.find("stopped by SIG" + signal + ": "), std::string::npos) << err;
  EXPECT_NE(err.find("the same command with --resume renders the other"), std::string::npos) << err;

  const auto manifest = nlohmann::json::parse(read_file(dir + "/out/manifest.json"));
  const size_t listed = manifest.at("frames").size();
  EXPECT_GE(listed, 2u);
  EXPECT_LT(listed, 300u);
  EXPECT_NE(err.find(std::to_string(listed) + " of 300 frames are finished"), std::string::npos)
      << err;
  const FolderReport report = check_output_folder(dir + "/out", "small.mkv");
  EXPECT_TRUE(report.problems.empty()) << report.describe();
  EXPECT_FALSE(report.has_video);

  const RunResult resumed = run_sdfreel("render t.toml --resume", dir);
  ASSERT_EQ(resumed.status, 0) << resumed.err;
  EXPECT_NE(resumed.err.find(std::to_string(listed) + " kept from before"), std::string::npos)
      << resumed.err;
  const FolderReport done = check_output_folder(dir + "/out", "small.mkv");
  EXPECT_TRUE(done.problems.empty()) << done.describe();
  EXPECT_TRUE(done.has_video);
  EXPECT_EQ(done.listed, 300);
}

TEST(Interrupt, SigintKeepsFinishedFramesAndResumeFinishes) {
  interrupt_then_resume("INT", "130");
}

TEST(Interrupt, SigtermKeepsFinishedFramesAndResumeFinishes) {
  interrupt_then_resume("TERM", "143");
}

}  // namespace
}  // namespace sdfreel::test
